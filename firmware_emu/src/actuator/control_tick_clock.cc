#include "hil/firmware_emu/actuator/control_tick_clock.h"

namespace hil::actuator {

bool ControlTickClock::TickDue(Time t) {
  if (t < next_tick_) return false;
  next_tick_ += timing_.control_period;
  return true;
}

bool ControlTickClock::CountTick(Time t, ControlTickCounters& c) {
  ++c.ticks;
  const bool missing = t >= timing_.first_command_due &&
                       (!c.last_command || t - *c.last_command > timing_.command_timeout);
  if (missing) {
    if (c.missing_commands == 0 || !last_missing_) c.first_missing = t;
    ++c.missing_commands;
  }
  last_missing_ = missing;
  return missing;
}

void ControlTickClock::Hold(Time t, double speed_mps, double steer_or_yaw_rate) {
  const Time t_effect = t == Time{} ? t : t + timing_.grid;
  pending_ = VehicleCommand{t_effect, speed_mps, steer_or_yaw_rate};
  next_ = t + timing_.grid;
}

std::optional<VehicleCommand> ControlTickClock::TakeVehicleCommand() {
  std::optional<VehicleCommand> c = pending_;
  pending_.reset();
  return c;
}

}  // namespace hil::actuator

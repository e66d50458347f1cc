#include "hil/firmware_emu/actuator/base_serial_device.h"

namespace hil::actuator {

BaseSerialDevice::BaseSerialDevice(const BaseSerialDeviceConfig& config)
    : cfg_(config), motors_(cfg_.motors), session_(cfg_.serial, motors_), loss_(cfg_.link_loss) {
  next_tick_ = Time{} + cfg_.control_period;
}

int BaseSerialDevice::baud(int port) const {
  (void)port;
  return static_cast<int>(cfg_.serial.baud);
}

void BaseSerialDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  (void)port;
  if (loss_.Cuts(t, bytes.size())) return;
  session_.OnHostBytes(t, bytes, out);
  if (session_.counters().motor_commands != seen_motor_commands_) {
    seen_motor_commands_ = session_.counters().motor_commands;
    counters_.last_command = t;
  }
}

void BaseSerialDevice::ControlTick(Time t) {
  ++counters_.ticks;
  const bool missing =
      t >= cfg_.first_command_due &&
      (!counters_.last_command || t - *counters_.last_command > cfg_.command_timeout);
  if (missing) {
    if (counters_.missing_commands == 0 || (!ticks_.empty() && !ticks_.back().missing))
      counters_.first_missing = t;
    ++counters_.missing_commands;
  }
  const double track = cfg_.motors.track_m, r = cfg_.motors.wheel_radius_m;
  BaseTickRecord rec;
  rec.t = t;
  rec.commanded_yaw_rate_radps =
      (motors_.target_speed_radps(kRightWheel) - motors_.target_speed_radps(kLeftWheel)) * r /
      track;
  rec.yaw_rate_radps = motors_.body_yaw_rate_radps();
  rec.speed_mps = motors_.body_speed_mps();
  rec.missing = missing;
  ticks_.push_back(rec);
}

void BaseSerialDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  (void)out;
  const Time t = truth.t;
  motors_.AdvanceTo(t);
  if (t >= next_tick_) {
    ControlTick(t);
    next_tick_ += cfg_.control_period;
  }
  // the wheels' state now drives the truth from the next grid instant on (the first, at t = 0,
  // from the start: the truth has no input before it), stamped exactly on it, as the steering
  // ECU's: an instant between grid points (t + 1 ns) is applied one grid step apart by the truth
  // integrated online and by its replay for the evaluation (truth.csv)
  const Time t_effect = t == Time{} ? t : t + cfg_.grid;
  pending_ = VehicleCommand{t_effect, motors_.body_speed_mps(), motors_.body_yaw_rate_radps()};
  next_ = t + cfg_.grid;
}

std::optional<VehicleCommand> BaseSerialDevice::TakeVehicleCommand() {
  std::optional<VehicleCommand> c = pending_;
  pending_.reset();
  return c;
}

}  // namespace hil::actuator

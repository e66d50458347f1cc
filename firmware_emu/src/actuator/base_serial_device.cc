#include "hil/firmware_emu/actuator/base_serial_device.h"

namespace hil::actuator {

BaseSerialDevice::BaseSerialDevice(const BaseSerialDeviceConfig& config)
    : cfg_(config),
      motors_(cfg_.motors),
      session_(cfg_.serial, motors_),
      tick_({cfg_.grid, cfg_.control_period, cfg_.command_timeout, cfg_.first_command_due}),
      loss_(cfg_.link_loss) {}

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
  const bool missing = tick_.CountTick(t, counters_);
  const double track = cfg_.motors.track_m, r = cfg_.motors.wheel_radius_m;
  BaseTickRecord rec;
  rec.t = t;
  rec.commanded_yaw_rate_radps =
      (motors_.target_speed_radps(kRightWheel) - motors_.target_speed_radps(kLeftWheel)) * r /
      track;
  rec.yaw_rate_radps = motors_.body_yaw_rate_radps();
  rec.speed_mps = motors_.body_speed_mps();
  rec.missing = missing;
  tick_tap_(rec);
}

void BaseSerialDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  (void)out;
  const Time t = truth.t;
  motors_.AdvanceTo(t);
  if (tick_.TickDue(t)) ControlTick(t);
  // the wheels' state drives the truth from the next grid instant on
  tick_.Hold(t, motors_.body_speed_mps(), motors_.body_yaw_rate_radps());
}

std::optional<VehicleCommand> BaseSerialDevice::TakeVehicleCommand() {
  return tick_.TakeVehicleCommand();
}

}  // namespace hil::actuator

#include "hil/firmware_emu/actuator/isobus_steering_device.h"

#include <cmath>

namespace hil::actuator {

IsobusSteeringDevice::IsobusSteeringDevice(const IsobusSteeringDeviceConfig& config)
    : cfg_(config), ecu_(cfg_.ecu), loss_(cfg_.link_loss) {
  next_tick_ = Time{} + cfg_.control_period;
  host_frames_.reserve(16);
}

int IsobusSteeringDevice::baud(int port) const {
  (void)port;
  return cfg_.slcan_baud;
}

void IsobusSteeringDevice::FromController(Time t, const CanFrame& frame) {
  if (loss_.Cuts(t, 1)) return;
  ++counters_.frames_from_controller;
  ecu_.OnFrame(t, frame);
  if (ecu_.counters().commands_accepted != seen_accepted_) {
    seen_accepted_ = ecu_.counters().commands_accepted;
    counters_.last_command = t;
  }
}

void IsobusSteeringDevice::OnBusFrame(Time t, const CanFrame& frame, DeviceOutput& out) {
  (void)out;
  if (cfg_.transport != IsobusTransport::kSocketCan) return;
  // a frame read late (real time) counts from the ECU's present on
  FromController(t < ecu_.now() ? ecu_.now() : t, frame);
}

void IsobusSteeringDevice::OnHostBytes(int port, Time t, std::string_view bytes,
                                       DeviceOutput& out) {
  (void)port;
  if (cfg_.transport != IsobusTransport::kSlcan) return;
  std::string reply;
  host_frames_.clear();
  adapter_.OnHostBytes(t, bytes, reply, host_frames_);
  if (!reply.empty()) out.serial.push_back({t, 0, std::move(reply), "SLCAN-REPLY", std::nullopt});
  const Time t_ecu = t < ecu_.now() ? ecu_.now() : t;
  for (const CanFrame& f : host_frames_) FromController(t_ecu, f);
}

void IsobusSteeringDevice::ControlTick(Time t) {
  ++counters_.ticks;
  const bool missing =
      t >= cfg_.first_command_due &&
      (!counters_.last_command || t - *counters_.last_command > cfg_.command_timeout);
  if (missing) {
    if (counters_.missing_commands == 0 || (!ticks_.empty() && !ticks_.back().missing))
      counters_.first_missing = t;
    ++counters_.missing_commands;
  }
  SteeringTickRecord rec;
  rec.t = t;
  rec.commanded_steer_rad = -ecu_.target_steer_angle_rad();
  rec.steer_rad = -ecu_.steer_angle_rad();
  rec.engaged = ecu_.engaged();
  rec.missing = missing;
  ticks_.push_back(rec);
}

void IsobusSteeringDevice::Send(DeviceOutput& ecu_out, DeviceOutput& out) {
  for (CanFrame& f : ecu_out.can) {
    if (cfg_.transport == IsobusTransport::kSocketCan) {
      out.can.push_back(f);
      continue;
    }
    std::string rec = adapter_.ToHost(f);
    if (!rec.empty()) out.serial.push_back({f.t, 0, std::move(rec), "SLCAN-FRAME", std::nullopt});
  }
  ecu_out.clear();
}

void IsobusSteeringDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  const double v = truth.speed_mps;
  ecu_.AdvanceTo(t, v);
  if (t >= next_tick_) {
    ControlTick(t);
    next_tick_ += cfg_.control_period;
  }
  while (ecu_.next_status_time() <= t) ecu_.EmitStatus(v, distance_m_, scratch_);
  Send(scratch_, out);
  distance_m_ += std::fabs(v) * ToSeconds(cfg_.grid);
  // the road wheels drive the truth from the next grid instant on (the first, at t = 0, from the
  // start), stamped exactly on it: an instant between grid points (t + 1 ns) is applied one grid
  // step apart by the truth integrated online and by its replay for the evaluation (the online
  // truth and truth.csv then differ by centimetres after a turn). The ECU's angle is positive
  // right, the truth's left.
  const Time t_effect = t == Time{} ? t : t + cfg_.grid;
  pending_ = VehicleCommand{t_effect, cfg_.speed_mps, -ecu_.steer_angle_rad()};
  next_ = t + cfg_.grid;
}

std::optional<VehicleCommand> IsobusSteeringDevice::TakeVehicleCommand() {
  std::optional<VehicleCommand> c = pending_;
  pending_.reset();
  return c;
}

}  // namespace hil::actuator

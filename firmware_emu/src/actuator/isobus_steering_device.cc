#include "hil/firmware_emu/actuator/isobus_steering_device.h"

#include <cmath>

namespace hil::actuator {

IsobusSteeringDevice::IsobusSteeringDevice(const IsobusSteeringDeviceConfig& config)
    : cfg_(config),
      ecu_(cfg_.ecu),
      tick_({cfg_.grid, cfg_.control_period, cfg_.command_timeout, cfg_.first_command_due}),
      loss_(cfg_.link_loss) {
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
  const bool missing = tick_.CountTick(t, counters_);
  SteeringTickRecord rec;
  rec.t = t;
  rec.commanded_steer_rad = -ecu_.target_steer_angle_rad();
  rec.steer_rad = -ecu_.steer_angle_rad();
  rec.engaged = ecu_.engaged();
  rec.missing = missing;
  if (rec.engaged) {
    const double e = rec.steer_rad - rec.commanded_steer_rad;
    engaged_error_sq_sum_rad2_ += e * e;
    ++engaged_ticks_;
  }
  tick_tap_(rec);
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
  if (tick_.TickDue(t)) ControlTick(t);
  while (ecu_.next_status_time() <= t) ecu_.EmitStatus(v, distance_m_, scratch_);
  Send(scratch_, out);
  distance_m_ += std::fabs(v) * ToSeconds(cfg_.grid);
  // the road wheels drive the truth from the next grid instant on (stamped on it: else the online
  // truth and truth.csv differ by centimetres after a turn). The ECU's angle is positive right,
  // the truth's left.
  tick_.Hold(t, cfg_.speed_mps, -ecu_.steer_angle_rad());
}

std::optional<VehicleCommand> IsobusSteeringDevice::TakeVehicleCommand() {
  return tick_.TakeVehicleCommand();
}

}  // namespace hil::actuator

#include "hil/firmware_emu/actuator/steering_ecu.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/actuator/first_order_rate_limited.h"

namespace hil::actuator {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace

SteeringEcu::SteeringEcu(const SteeringEcuConfig& config) : cfg_(config) {}

bool SteeringEcu::SourceAccepted(std::uint8_t sa) const {
  return std::find(cfg_.accepted_sources.begin(), cfg_.accepted_sources.end(), sa) !=
         cfg_.accepted_sources.end();
}

double SteeringEcu::curvature_left_per_m() const {
  return -std::tan(delta_rad_) / cfg_.wheelbase_m;
}

void SteeringEcu::OnFrame(Time t, const CanFrame& frame) {
  AdvanceTo(t, speed_mps_);
  if (!frame.extended) return;
  const J1939IdFields id = SplitJ1939Id(frame.id);
  if (id.pgn != kPgnGuidanceSystemCommand) return;
  if (id.destination != cfg_.source_address && id.destination != 0xFF) {
    ++counters_.not_addressed;
    return;
  }
  if (!SourceAccepted(id.source)) {
    ++counters_.unknown_source;
    return;
  }
  GuidanceSystemCommand cmd;
  const CommandFrameError err = DecodeGuidanceSystemCommand(frame, cmd);
  if (err == CommandFrameError::kWrongLength) {
    ++counters_.wrong_length;
    return;
  }
  if (err == CommandFrameError::kCurvatureOutOfRange) {
    ++counters_.out_of_range;
  } else {
    ++counters_.commands_accepted;
    last_valid_arrival_ = t;
  }
  if (queue_size_ == static_cast<int>(queue_.size())) {
    ++counters_.queue_overflow;
    return;
  }
  queue_[(queue_head_ + queue_size_) % queue_.size()] = Pending{t + cfg_.command_latency, cmd};
  ++queue_size_;
}

void SteeringEcu::AdvanceTo(Time t, double speed_mps) {
  speed_mps_ = speed_mps;
  CheckSpeed();
  while (true) {
    Time next = t;
    if (queue_size_ > 0) next = std::min(next, queue_[queue_head_].t_effect);
    const Time deadline = last_valid_arrival_ + cfg_.command_timeout;
    const bool watchdog_due = engaged_ && deadline <= next;
    if (watchdog_due) next = deadline;
    if (next > now_) {
      Integrate(ToSeconds(next - now_));
      now_ = next;
    }
    if (watchdog_due) {
      ++counters_.watchdog_trips;
      counters_.last_watchdog_trip = deadline;
      Exit(ExitReason::kRemoteCommandTimeout);
      continue;
    }
    if (queue_size_ > 0 && queue_[queue_head_].t_effect <= now_) {
      const GuidanceSystemCommand cmd = queue_[queue_head_].cmd;
      queue_head_ = (queue_head_ + 1) % static_cast<int>(queue_.size());
      --queue_size_;
      Apply(cmd);
      continue;
    }
    if (now_ >= t) break;
  }
}

void SteeringEcu::Integrate(double dt_s) {
  // The valve acts while the position error exceeds the deadband and closes where it enters it.
  const double e = target_rad_ - delta_rad_;
  const double deadband_rad = cfg_.deadband_deg * kDegToRad;
  if (std::fabs(e) <= deadband_rad) return;
  delta_rad_ = AdvanceFirstOrderRateLimited(delta_rad_, target_rad_, cfg_.time_constant_s,
                                            cfg_.max_steer_rate_dps * kDegToRad, dt_s)
                   .x;
  if (std::fabs(target_rad_ - delta_rad_) < deadband_rad)
    delta_rad_ = target_rad_ - (e > 0 ? deadband_rad : -deadband_rad);
}

void SteeringEcu::Apply(const GuidanceSystemCommand& cmd) {
  if (cmd.curvature_raw > kCurvatureRawMax) {
    Exit(ExitReason::kRemoteCommandOutOfRange);
    return;
  }
  switch (cmd.status) {
    case CurvatureCommandStatus::kIntendedToSteer: {
      if (reset_required_) return;  // still asking for "not intended to steer" first
      if (!engaged_) ++counters_.engagements;
      engaged_ = true;
      exit_reason_ = ExitReason::kAllClear;
      CheckSpeed();
      if (!engaged_) return;
      const double max_rad = cfg_.max_steer_deg * kDegToRad;
      const double wanted = std::atan(cmd.curvature_per_km * 1e-3 * cfg_.wheelbase_m);
      limit_status_ = wanted > max_rad ? 2 : (wanted < -max_rad ? 3 : 0);
      target_rad_ = std::clamp(wanted, -max_rad, max_rad);
      return;
    }
    case CurvatureCommandStatus::kNotIntendedToSteer:
      reset_required_ = false;
      exit_reason_ = ExitReason::kAllClear;
      [[fallthrough]];
    case CurvatureCommandStatus::kNotAvailable:
      engaged_ = false;
      limit_status_ = 0;
      if (cfg_.center_on_disengage)
        target_rad_ = 0;
      else
        target_rad_ = delta_rad_;
      return;
    case CurvatureCommandStatus::kError:
      Exit(ExitReason::kError);
      return;
  }
}

void SteeringEcu::Exit(ExitReason reason) {
  engaged_ = false;
  reset_required_ = true;
  exit_reason_ = reason;
  limit_status_ = 0;
  target_rad_ = cfg_.center_on_disengage ? 0.0 : delta_rad_;
}

void SteeringEcu::CheckSpeed() {
  if (!engaged_) return;
  const double v = std::fabs(speed_mps_);
  if (cfg_.min_engage_speed_mps > 0 && v < cfg_.min_engage_speed_mps)
    Exit(ExitReason::kSpeedTooLow);
  else if (v > cfg_.max_engage_speed_mps)
    Exit(ExitReason::kSpeedTooHigh);
}

GuidanceMachineInfo SteeringEcu::machine_info() const {
  GuidanceMachineInfo m;
  m.estimated_curvature_per_km = 1e3 * std::tan(delta_rad_) / cfg_.wheelbase_m;
  m.mechanical_system_lockout = 0;
  m.steering_system_readiness = 1;
  m.steering_input_position_status = 3;
  m.request_reset_command_status = reset_required_ ? 1 : 0;
  m.guidance_limit_status = limit_status_;
  m.exit_reason_code = static_cast<std::uint8_t>(exit_reason_);
  m.remote_engage_switch_status = 3;
  return m;
}

void SteeringEcu::EmitStatus(double speed_mps, double distance_m, DeviceOutput& out) {
  const Time t = next_status_;
  out.can.push_back(
      EncodeGuidanceMachineInfo(t, cfg_.priority, cfg_.source_address, 0xFF, machine_info()));
  WheelBasedSpeedDistance w;
  w.speed_mps = speed_mps;
  w.distance_m = distance_m;
  w.direction = speed_mps < 0 ? 0 : 1;
  out.can.push_back(EncodeWheelBasedSpeedDistance(t, cfg_.priority, cfg_.source_address, w));
  next_status_ = t + cfg_.status_period;
}

}  // namespace hil::actuator

#include "hil/firmware_emu/actuator/wheel_motors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/actuator/first_order_rate_limited.h"

namespace hil::actuator {

WheelMotors::WheelMotors(const WheelMotorsConfig& config)
    : cfg_(config), faults_(cfg_.faults, cfg_.fault_seed) {
  speed_radps_ = {cfg_.initial_wheel_speed_radps, cfg_.initial_wheel_speed_radps};
  target_radps_ = speed_radps_;
}

void WheelMotors::Command(Time t, double left_radps, double right_radps) {
  AdvanceTo(t);
  ++counters_.commands;
  last_command_ = t;
  ever_commanded_ = true;
  tripped_ = false;
  const double m = faults_.SpeedLimit(t, cfg_.max_wheel_speed_radps);
  const bool beyond = std::fabs(left_radps) > m || std::fabs(right_radps) > m;
  if (beyond) ++counters_.saturated_commands;
  if (!faults_.empty()) faults_.NoteCommand(t, beyond);
  const Duration added = faults_.empty() ? Duration{} : faults_.AddedLatency(t, counters_.commands);
  if (queue_size_ == static_cast<int>(queue_.size())) {
    ++counters_.queue_overflow;
    return;
  }
  // the limit applies as the wheels turn (Integrate); the line delivers in order
  last_effect_ = std::max(t + cfg_.command_latency + added, last_effect_);
  queue_[(queue_head_ + queue_size_) % queue_.size()] =
      Pending{last_effect_, {left_radps, right_radps}};
  ++queue_size_;
}

void WheelMotors::AdvanceTo(Time t) {
  while (true) {
    Time next = t;
    if (queue_size_ > 0) next = std::min(next, queue_[queue_head_].t_effect);
    const Time deadline = last_command_ + cfg_.command_timeout;
    if (!faults_.empty()) next = std::min(next, faults_.NextBoundaryAfter(now_));
    const bool watchdog_due = ever_commanded_ && !tripped_ && deadline <= next;
    if (watchdog_due) next = deadline;
    if (next > now_) {
      Integrate(ToSeconds(next - now_));
      now_ = next;
    }
    if (watchdog_due) {
      tripped_ = true;
      target_radps_ = {0.0, 0.0};
      queue_size_ = 0;
      ++counters_.watchdog_trips;
      counters_.last_watchdog_trip = deadline;
      continue;
    }
    if (queue_size_ > 0 && queue_[queue_head_].t_effect <= now_) {
      target_radps_ = queue_[queue_head_].target_radps;
      queue_head_ = (queue_head_ + 1) % static_cast<int>(queue_.size());
      --queue_size_;
      continue;
    }
    if (now_ >= t) break;
  }
}

void WheelMotors::Integrate(double dt_s) {
  const double m = faults_.SpeedLimit(now_, cfg_.max_wheel_speed_radps);
  const bool stuck = faults_.Stuck(now_);  // the drive holds its output
  bool clamped = false;
  for (int w = 0; w < 2; ++w) {
    const double target = std::clamp(target_radps_[w], -m, m);
    clamped = clamped || target != target_radps_[w];
    if (stuck) {
      angle_rad_[w] += speed_radps_[w] * dt_s;
      continue;
    }
    const LagStep s = AdvanceFirstOrderRateLimited(speed_radps_[w], target, cfg_.time_constant_s,
                                                   cfg_.max_wheel_accel_radps2, dt_s);
    speed_radps_[w] = s.x;
    angle_rad_[w] += s.integral;
  }
  if (clamped) counters_.saturated_s += dt_s;
  if (!faults_.empty()) faults_.NoteInterval(now_, dt_s, clamped);
}

void WheelMotors::ResetEncoders() { angle_rad_ = {0.0, 0.0}; }

double WheelMotors::ground_speed_mps(int wheel) const {
  return speed_radps_[wheel] * cfg_.wheel_radius_m * (1.0 - cfg_.slip[wheel]);
}

double WheelMotors::body_speed_mps() const {
  return 0.5 * (ground_speed_mps(kLeftWheel) + ground_speed_mps(kRightWheel));
}

double WheelMotors::body_yaw_rate_radps() const {
  return (ground_speed_mps(kRightWheel) - ground_speed_mps(kLeftWheel)) /
         (cfg_.icr_expansion * cfg_.track_m);
}

std::int64_t WheelMotors::encoder_count(int wheel) const {
  // 1e-9 count guards the floor against rounding noise of the angle's sum (a shaft exactly on an
  // edge counts that edge).
  const double counts = angle_rad_[wheel] / (2.0 * std::numbers::pi) * cfg_.encoder_counts_per_rev;
  return static_cast<std::int64_t>(std::floor(counts + 1e-9));
}

}  // namespace hil::actuator

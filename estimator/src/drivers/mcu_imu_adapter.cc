#include "hil/estimator/drivers/mcu_imu_adapter.h"

namespace hil::estimator::drivers {

std::optional<ImuSample> McuImuAdapter::Add(const McuFrame& f) {
  switch (f.type) {
    case McuFrame::Type::kStatus:
      if (f.sequence == 0 && stats_.pulses > 0) {
        clock_.Reset();
        have_prev_ = false;
        ++stats_.resets;
      }
      accel_scale_ = f.accel_scale_mps2_per_lsb;
      gyro_scale_ = f.gyro_scale_radps_per_lsb;
      return std::nullopt;
    case McuFrame::Type::kTimePulse:
      if (f.time_valid) {
        const GpsNs t = static_cast<GpsNs>(f.gps_week) * 604800LL * kNsPerSecond + static_cast<GpsNs>(f.tow_ms) * 1'000'000LL;
        clock_.AddPulse(clock_.Unwrap(f.tick), t);
        ++stats_.pulses;
      }
      return std::nullopt;
    case McuFrame::Type::kMag:
      clock_.Unwrap(f.tick);
      return std::nullopt;
    case McuFrame::Type::kImu:
      break;
  }
  const std::int64_t tick = clock_.Unwrap(f.tick);
  if (accel_scale_ == 0 || gyro_scale_ == 0) {
    ++stats_.imu_no_scale;
    return std::nullopt;
  }
  Eigen::Vector3d w, a;
  for (int k = 0; k < 3; ++k) {
    w[k] = f.gyro_raw[k] * static_cast<double>(gyro_scale_);
    a[k] = f.accel_raw[k] * static_cast<double>(accel_scale_);
  }
  const auto t = clock_.ToGps(tick);
  if (!t) {
    ++stats_.imu_no_time;
    have_prev_ = false;
    return std::nullopt;
  }
  std::optional<ImuSample> out;
  if (have_prev_) {
    const double dt = static_cast<double>(tick - prev_tick_) / clock_.rate_hz();
    if (dt > 0 && dt <= max_gap_s_) {
      ImuSample s;
      s.t = *t;
      s.dt_s = dt;
      s.delta_angle_B_rad = 0.5 * (prev_w_ + w) * dt;
      s.delta_velocity_B_mps = 0.5 * (prev_f_ + a) * dt;
      out = s;
      ++stats_.imu_out;
    } else {
      ++stats_.imu_gap;
    }
  }
  have_prev_ = true;
  prev_tick_ = tick;
  prev_w_ = w;
  prev_f_ = a;
  return out;
}

}  // namespace hil::estimator::drivers

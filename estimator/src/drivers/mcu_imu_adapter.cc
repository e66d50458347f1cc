#include "hil/estimator/drivers/mcu_imu_adapter.h"

namespace hil::estimator::drivers {

std::optional<ImuSample> McuImuAdapter::Add(const McuFrame& f) {
  switch (f.type) {
    case McuFrame::Type::kStatus:
      if (f.sequence == 0 && stats_.pulses > 0) {
        clock_.Reset();
        increments_.Restart();
        ++stats_.resets;
      }
      accel_scale_ = f.accel_scale_mps2_per_lsb;
      gyro_scale_ = f.gyro_scale_radps_per_lsb;
      return std::nullopt;
    case McuFrame::Type::kTimePulse:
      if (f.time_valid) {
        const GpsTime t = GpsTimeFromWeek(f.gps_week, std::int64_t{f.tow_ms} * 1'000'000LL);
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
    increments_.Restart();
    return std::nullopt;
  }
  const std::uint64_t gaps_before = increments_.gaps();
  auto out = increments_.Add(*t, w, a, static_cast<double>(tick - prev_tick_) / clock_.rate_hz());
  prev_tick_ = tick;
  if (out) ++stats_.imu_out;
  if (increments_.gaps() != gaps_before) ++stats_.imu_gap;
  return out;
}

}  // namespace hil::estimator::drivers

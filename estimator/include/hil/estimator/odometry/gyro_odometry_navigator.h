#pragma once
/// @file
/// navd's gyro + wheel-odometry navigator (paper 001): the MCU IMU's samples and the base's
/// encoder counts into GyroOdometryFilter, transport-free.
/// - Static alignment: for the first `align_s` of IMU samples the vehicle stands still; the mean
///   specific force gives the up axis (whatever the IMU's axes), the mean rate about it the
///   initial gyro bias. Then the filter starts at the configured pose.
/// - Each IMU sample after it: Δθ_up = Δθ_B · up into the filter, and a history entry (time, raw
///   integrated Δθ_up, ψ) in a fixed ring so that an encoder interval that arrives late finds the
///   raw gyro increment and the heading over its own span.
/// - Each encoder sample (cumulative signed counts of each wheel, 32-bit wrapping): the interval
///   from the previous one gives Δs = (Δs_L + Δs_R)/2 and Δψ_odo = (Δs_R − Δs_L)/track, with
///   Δs = Δcounts · 2π r / counts_per_rev (the encoder sees the shaft: slip is not seen).
/// - Output at time t: the filter's pose moved on by the last interval's speed from the encoder
///   sample's time to t.
/// Fixed-size, no allocation.

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/odometry/gyro_odometry_filter.h"
#include "hil/estimator/samples.h"
#include "hil/estimator/time_types.h"

namespace hil::estimator::odometry {

struct WheelOdometryConfig {
  double wheel_radius_m = 0.1, track_m = 0.5;
  int counts_per_rev = 1200;
  double align_s = 2.0;  ///< static alignment at the start (the vehicle stands still)
  Eigen::Vector2d initial_p_EN_m{0, 0};
  double initial_yaw_rad = 0;  ///< ENU, counter-clockwise from east
  GyroOdometryParams filter;
};

/// The base's cumulative encoder counts at time t.
struct EncoderSample {
  GpsTime t{};
  std::int32_t left_counts = 0, right_counts = 0;
};

struct PlanarSolution {
  GpsTime t{};
  Eigen::Vector2d p_EN_m{0, 0};
  double yaw_rad = 0, speed_mps = 0, yaw_rate_radps = 0;
  Eigen::Vector2d position_std_m{0, 0};
  double yaw_std_rad = 0, bias_radps = 0;
};

struct WheelOdometryStats {
  std::uint64_t encoder_samples = 0, out_of_order = 0, outside_history = 0;
};

class GyroOdometryNavigator {
 public:
  explicit GyroOdometryNavigator(const WheelOdometryConfig& c) : config_(c), filter_(c.filter) {}
  void OnImu(const ImuSample& s);
  void OnEncoders(const EncoderSample& e);
  bool aligned() const { return filter_.initialized(); }
  /// The solution at t (after the last IMU sample); nullopt before the alignment ends.
  std::optional<PlanarSolution> Output(GpsTime t) const;
  const GyroOdometryFilter& filter() const { return filter_; }
  const WheelOdometryStats& stats() const { return stats_; }

 private:
  struct HistoryEntry {
    GpsTime t{};
    double theta_raw_rad = 0, yaw_rad = 0;
  };
  static constexpr int kHistory = 512;
  void Align(const ImuSample& s);
  bool Lookup(GpsTime t, HistoryEntry& out) const;

  WheelOdometryConfig config_;
  GyroOdometryFilter filter_;
  Eigen::Vector3d align_dtheta_ = Eigen::Vector3d::Zero(), align_dv_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d up_B_ = Eigen::Vector3d::UnitZ();
  double align_time_s_ = 0, theta_raw_rad_ = 0, last_rate_radps_ = 0;
  std::array<HistoryEntry, kHistory> history_{};
  int history_pos_ = 0, history_fill_ = 0;
  std::optional<EncoderSample> last_encoders_;
  double speed_mps_ = 0;
  WheelOdometryStats stats_;
};

}  // namespace hil::estimator::odometry

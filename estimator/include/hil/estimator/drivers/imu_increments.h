#pragma once
/// @file
/// Rate samples → the filter's IMU increments. Every IMU input (the MCU's binary frames, the Razor
/// text, J1939 on CAN) delivers instantaneous angular rate and specific force at a time; the filter
/// wants Δθ and Δv over each interval. The trapezoid rule over consecutive samples gives them; an
/// interval that is not positive or longer than `max_gap_s` is dropped and restarts the sequence.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

class ImuIncrements {
 public:
  explicit ImuIncrements(double max_gap_s) : max_gap_s_(max_gap_s) {}

  /// The increment from the previous sample to this one (none for the first sample or after a
  /// gap). `dt_s` is the interval by the sensor's own clock when the caller has one (MCU ticks);
  /// otherwise it is t − t_previous.
  std::optional<ImuSample> Add(GpsTime t, const Eigen::Vector3d& w_B_radps,
                               const Eigen::Vector3d& f_B_mps2,
                               std::optional<double> dt_s = std::nullopt);
  /// Forgets the previous sample (a reset, an unusable sample).
  void Restart() { have_prev_ = false; }

  std::uint64_t increments() const { return increments_; }
  std::uint64_t gaps() const { return gaps_; }

 private:
  double max_gap_s_;
  bool have_prev_ = false;
  GpsTime prev_t_{};
  Eigen::Vector3d prev_w_ = Eigen::Vector3d::Zero(), prev_f_ = Eigen::Vector3d::Zero();
  std::uint64_t increments_ = 0, gaps_ = 0;
};

}  // namespace hil::estimator::drivers

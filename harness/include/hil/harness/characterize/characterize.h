#pragma once
/// @file
/// hil characterize's analysis: an IMU log resampled onto a uniform grid (imu_series.h), a window
/// of it (given, or the longest still period), then per axis of the gyro and the accelerometer the
/// overlapping Allan deviation at octave-spaced τ, the Welch PSD and the noise terms fitted to
/// both (noise_fit.h).

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/characterize/imu_series.h"
#include "hil/harness/characterize/noise_fit.h"
#include "hil/harness/characterize/still_periods.h"

namespace hil::harness {

struct CharacterizeOptions {
  std::optional<double> from_s, to_s;  ///< window, seconds from the log's first sample
  bool still = false;                  ///< analyse the longest still period (within the window)
  StillOptions still_options;
  double step_s = 0;            ///< grid step; 0: the log's median interval (to 1 µs)
  std::size_t psd_segment = 0;  ///< Welch segment (samples); 0: DefaultWelchSegment
};

/// Thrown when `still` was asked and the log has no still period: a verdict, not bad input.
class NoStillPeriod : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using AxisLists = std::array<std::vector<double>, 3>;  ///< x, y, z

struct Characterization {
  std::string format;
  std::vector<std::string> notes;
  double log_start_s = 0, log_length_s = 0;  ///< the log's own time scale
  double step_s = 0, max_gap_s = 0;
  double from_s = 0, to_s = 0;             ///< the analysed window, seconds from the log's start
  std::size_t samples = 0;                 ///< grid cells analysed
  UniformImu window;                       ///< those cells (t0_s on the log's time scale)
  std::vector<StillPeriod> still_periods;  ///< of the whole log
  Eigen::Vector3d mean_gyro_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_accel_mps2 = Eigen::Vector3d::Zero();
  std::vector<double> tau_s;
  AxisLists adev_gyro_radps, adev_accel_mps2;
  std::array<NoiseTerms, 3> gyro_terms, accel_terms;
  std::vector<double> psd_freq_hz;
  AxisLists psd_gyro_rad2ps2_per_hz, psd_accel_m2ps4_per_hz;
  std::size_t psd_segment = 0, psd_segments = 0;
  double psd_band_lo_hz = 0, psd_band_hi_hz = 0;  ///< where the PSD's white level was read
  Eigen::Vector3d psd_white_gyro = Eigen::Vector3d::Zero();   ///< N, rad/√s
  Eigen::Vector3d psd_white_accel = Eigen::Vector3d::Zero();  ///< N, m/s/√s
};

/// @throws std::invalid_argument for a window outside the log or too short (fewer than 64
/// samples), NoStillPeriod.
Characterization Characterize(const ImuSeries& log, const CharacterizeOptions& o);

}  // namespace hil::harness

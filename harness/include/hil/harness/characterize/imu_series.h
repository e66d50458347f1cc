#pragma once
/// @file
/// An IMU log as piecewise-constant rates (hil characterize): interval k holds the mean angular
/// rate and specific force over [t_s[k], t_s[k+1]). Increment logs (KF-GINS) give exactly that;
/// sample logs (CSV, MCU captures) hold each sample until the next one. ResampleUniform turns it
/// into means over a uniform grid by integrating (angle and velocity) and differencing at the grid
/// points: irregular or repeated samples do not bend the Allan curve as a uniform-index series
/// would, and a log that is already uniform at the grid's step comes out unchanged.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

struct ImuSeries {
  std::string format;       ///< kfgins, csv-timetag, capture
  std::vector<double> t_s;  ///< interval boundaries (n + 1), seconds on the log's own time scale
  std::vector<Eigen::Vector3d> gyro_radps;  ///< n interval means, sensor axes
  std::vector<Eigen::Vector3d> accel_mps2;  ///< n interval means, sensor axes
  /// What the reader wants said in the report (time base, skipped fragments, ...).
  std::vector<std::string> notes;
  std::size_t size() const { return gyro_radps.size(); }
};

/// Means over a uniform grid: cell j covers [t0_s + j·step_s, t0_s + (j+1)·step_s).
struct UniformImu {
  double t0_s = 0, step_s = 0;
  std::vector<Eigen::Vector3d> gyro_radps, accel_mps2;
  double max_gap_s = 0;  ///< the longest source interval the resampled log covered (gaps)
  std::size_t size() const { return gyro_radps.size(); }
};

/// The median interval of a series (the natural grid step). @throws std::invalid_argument when
/// the series has no interval.
double MedianIntervalS(const ImuSeries& s);

/// Means of `s` over the grid from its first boundary with `step_s` (the last partial cell is
/// dropped). @throws std::invalid_argument for step_s <= 0 or a series shorter than one step.
UniformImu ResampleUniform(const ImuSeries& s, double step_s);

/// Cells [first, first + count) of `u` as a UniformImu of their own.
UniformImu Slice(const UniformImu& u, std::size_t first, std::size_t count);

}  // namespace hil::harness

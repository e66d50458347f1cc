#pragma once
/// @file
/// navd's filter (the Navigator's error-state EKF) on a KF-GINS dataset: the IMU file's increments
/// at their own times, the GNSS file's fixes fused at their times of validity (the IMU interval
/// that holds a fix is split there), the initial state from the configuration at the first IMU
/// epoch at or after starttime, and one line per IMU epoch in KF-GINS's three result files.
/// The loop allocates nothing: lines are read into fixed buffers, results formatted into one.

#include <cstdint>

#include "hil/estimator/datasets/kfgins_config.h"
#include "hil/estimator/navigator.h"

namespace hil::estimator::datasets {

/// What one run did (counters for the report; consistency without a truth).
struct KfginsRunResult {
  std::uint64_t imu_epochs = 0;    ///< IMU lines used (after starttime, up to endtime)
  std::uint64_t gnss_records = 0;  ///< GNSS lines pushed (after starttime)
  std::uint64_t gnss_fused = 0, gnss_rejected = 0, gnss_resets = 0, imu_gaps = 0;
  double mean_nis_pos = 0;  ///< mean NIS of the accepted position updates (3 when consistent)
  double first_sow = 0, last_sow = 0;
  double wall_s = 0;  ///< the whole run: reading, filtering and writing
  double cpu_s = 0;   ///< the process's CPU time over the same (what a loaded machine cannot skew)
};

/// The Navigator's parameters for a KF-GINS configuration: its IMU noise (ARW, VRW), its bias
/// Gauss–Markov σ and τ as navd's random walk of the same variance growth (q = σ·√(2/τ)), its
/// initial σ (navd takes one σ for all three position and velocity axes: the largest), its lever
/// arm; no fusion delay (the files are complete); navd's own gating and nothing else switched on.
NavigatorParams NavigatorParamsFromKfgins(const KfginsConfig& c);

/// Runs `params` (e.g. NavigatorParamsFromKfgins, or a navd.conf's) on the configuration's files.
/// `self_align`: the Navigator aligns itself as navd does online (levelling from the specific
/// force, heading from the fixes' velocity) instead of starting from initpos/initvel/initatt;
/// the result files then start at the alignment.
/// @throws DatasetError for a missing or bad file (naming file, line and field).
KfginsRunResult RunKfgins(const KfginsConfig& c, const NavigatorParams& params,
                          bool self_align = false);

}  // namespace hil::estimator::datasets

#pragma once
/// @file
/// A small deterministic generator of KF-GINS-format test data from our truth (the CVODE
/// TruthIntegrator: a bicycle-model vehicle on a boustrophedon field pattern) and sensor models
/// of our own: IMU increments (Simpson's rule on the truth's angular rate and specific force, plus
/// turn-on bias, first-order Gauss–Markov bias drift and white noise), RTK-like GNSS fixes of the
/// antenna (white noise), optional GNSS outages. It writes, in one folder:
///   IMU.txt   sow dθx dθy dθz dvx dvy dvz            (rad, m/s, body FRD, increments)
///   GNSS.txt  sow lat lon h σN σE σD                 (deg, m; the σ the receiver reports)
///   truth.nav week sow lat lon h vN vE vD roll pitch yaw (the IMU's truth at every IMU epoch)
///   kf-gins.yaml  a KF-GINS configuration for them (initial state from the truth)
/// Same options and seed → the same bytes.

#include <cstdint>
#include <string>
#include <vector>

namespace hil::harness {

struct KfginsDatasetOptions {
  double duration_s = 60;
  double imu_rate_hz = 200;
  double gnss_rate_hz = 1;
  std::vector<double> outage_start_s;  ///< scenario seconds at which a GNSS outage begins
  double outage_length_s = 10;
  std::uint64_t seed = 1;
  double start_sow = 456300.0;  ///< GPS seconds of week of scenario time 0
  /// consumer MEMS (ICM-20602 class, UNVERIFIED datasheet-like values; see the README)
  double gyro_arw_deg_rthr = 0.3, gyro_turn_on_bias_deg_s = 0.05, gyro_bias_instability_deg_hr = 10;
  double accel_vrw_mps_rthr = 0.1, accel_turn_on_bias_mg = 5, accel_bias_instability_mg = 0.05;
  double bias_tau_s = 300;
  double gnss_std_h_m = 0.01, gnss_std_v_m = 0.02;  ///< RTK fixed, white, 1σ
};

struct KfginsDatasetResult {
  std::uint64_t imu_lines = 0, gnss_lines = 0;
};

/// Writes the dataset into `dir` (created if missing).
/// @throws std::runtime_error when a file cannot be written.
KfginsDatasetResult WriteKfginsDataset(const KfginsDatasetOptions& o, const std::string& dir);

}  // namespace hil::harness

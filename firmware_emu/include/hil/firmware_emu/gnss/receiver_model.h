#pragma once
/// @file
/// @system
/// name: ReceiverModel (standalone GNSS receiver error model)
/// input: TruthSample of the vehicle at each navigation epoch, antenna lever arm p_BA_B
/// output: GnssFix (protocol-neutral) at t_validity = epoch time
/// rate: the navigation rate (1 Hz for the NEO-5M default)
/// @endsystem
///
/// Position error is a first-order Gauss–Markov process per axis (east, north, up) with a
/// configured standard deviation and correlation time, which reproduces the smooth metre-level
/// drift and lag-1 autocorrelation (≈0.8 at 1 Hz for τ ≈ 4.5 s) of real standalone receivers.
/// Velocity error is white with a configured sigma. All randomness comes from the seed.

#include <cstdint>
#include <random>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/firmware_emu/truth_sample.h"

namespace hil::gnss {

/// Error and reporting parameters of one receiver; constant for a run.
struct ReceiverModelConfig {
  double horizontal_sigma_m = 0.35;   ///< per-axis standard deviation of east/north error
  double vertical_sigma_m = 0.8;      ///< standard deviation of the up error
  double correlation_time_s = 4.5;    ///< Gauss–Markov correlation time of position errors
  double velocity_sigma_mps = 0.03;   ///< white velocity noise per axis
  double geoid_separation_m = -20.0;  ///< geoid height N at the site (MSL = ellipsoid − N)
  int num_sv = 8;                     ///< satellites used
  double hdop = 1.1, vdop = 1.7, pdop = 2.0;
  Eigen::Vector3d p_BA_B_m = Eigen::Vector3d::Zero();  ///< antenna lever arm from the body origin
};

/// Receiver error model; one instance per emulated receiver, deterministic for a seed.
class ReceiverModel {
 public:
  ReceiverModel(const ReceiverModelConfig& config, std::uint64_t seed);

  /// Produces the fix of the epoch at `truth.t`, advancing the error processes by `dt_s`
  /// (the time since the previous call). `unix_ns` is the epoch's UTC instant.
  GnssFix Calc(const TruthSample& truth, std::int64_t unix_ns, double dt_s);

  /// Current position error of the antenna in ENU (m), for diagnostics and tests.
  const Eigen::Vector3d& position_error_N_m() const { return err_N_m_; }

 private:
  ReceiverModelConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Eigen::Vector3d err_N_m_ = Eigen::Vector3d::Zero();
  bool started_ = false;
};

}  // namespace hil::gnss

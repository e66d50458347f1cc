#pragma once
/// @file
/// @system
/// name: ReceiverModel (standalone GNSS receiver error model)
/// input: TruthSample of the vehicle at each navigation epoch, antenna lever arm p_BA_B,
///        the epoch's DOP scale and scripted glitches (ErrorInputs)
/// output: GnssFix (protocol-neutral) at t_validity = epoch time: position, velocity, accuracies
/// rate: the navigation rate (1 Hz for the NEO-5M default)
/// @endsystem
///
/// Position error per axis (east, north, up) = scale × (common + own) + glitches, where
///  - `common` is a first-order Gauss–Markov process seeded by the scenario's common GNSS seed,
///    identical in every receiver of the scenario (atmosphere, orbit and clock errors shared by
///    receivers a few metres apart), carrying `common_fraction` of the variance;
///  - `own` is an independent Gauss–Markov process of this receiver (multipath, noise), carrying
///    the rest. Averaging N receivers therefore reduces the error RMS only to
///    σ·√(c + (1−c)/N) (c = 0.46: 39.1 → 31.3 cm for N = 3, as in seed 000's paper);
///  - `scale` is the epoch's DOP over the reference DOP (errors grow when the geometry worsens);
///  - glitches: a position step (offset) and a multipath burst (extra Gauss–Markov error with a
///    2 s correlation time), both scripted by the device's fault list.
/// The correlation time (default 4.5 s) gives the lag-1 autocorrelation ≈ 0.8 at 1 Hz and the
/// smooth drift of real u-blox 5 captures. Velocity error is white per axis (a small non-zero
/// speed when stationary). Reported accuracies equal the modelled 1-sigma statistics:
/// hAcc = √(σe² + σn²), vAcc = σu, pAcc = √(hAcc² + vAcc²), sAcc = √3·σv.
/// All randomness comes from the seeds; the sequence of draws does not depend on the faults.

#include <cstdint>
#include <memory>
#include <random>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/geoid_grid.h"
#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/firmware_emu/truth_sample.h"

namespace hil::gnss {

/// Error and reporting parameters of one receiver; constant for a run.
struct ReceiverModelConfig {
  double horizontal_sigma_m =
      0.35;                         ///< per-axis standard deviation of east/north error at hdop_ref
  double vertical_sigma_m = 0.8;    ///< standard deviation of the up error at vdop_ref
  double correlation_time_s = 4.5;  ///< Gauss–Markov correlation time of position errors
  double velocity_sigma_mps = 0.03;  ///< white velocity noise per axis
  double common_fraction = 0.46;  ///< share of the position error variance common to all receivers
  /// Geoid height N (MSL = ellipsoid − N): from this EGM96 grid at each fix's position, as a
  /// u-blox 5 computes it; without a grid, the fixed value below.
  std::shared_ptr<const GeoidGrid> geoid;
  double geoid_separation_m = -20.0;                   ///< N when `geoid` is null
  double hdop_ref = 1.0, vdop_ref = 1.6;               ///< DOPs at which the sigmas above hold
  Eigen::Vector3d p_BA_B_m = Eigen::Vector3d::Zero();  ///< antenna lever arm from the body origin
};

/// Per-epoch inputs from the rest of the receiver (geometry) and the fault timeline.
struct ErrorInputs {
  double h_scale = 1.0, v_scale = 1.0;                   ///< hdop/hdop_ref, vdop/vdop_ref
  Eigen::Vector3d offset_N_m = Eigen::Vector3d::Zero();  ///< position step glitch (ENU)
  double multipath_sigma_m = 0.0;                        ///< burst: extra error sigma per axis
  /// Accuracy the receiver adds to its own estimate (1 sigma, m): the sky's multipath seen in its
  /// residuals, an RTK float solution. Combined with the model's by root sum of squares.
  double extra_h_acc_m = 0.0, extra_v_acc_m = 0.0;
};

/// Receiver error model; one instance per emulated receiver, deterministic for its seeds.
class ReceiverModel {
 public:
  /// @param seed this receiver's own error stream
  /// @param common_seed the scenario-wide stream shared by all receivers (0: seed + 1)
  ReceiverModel(const ReceiverModelConfig& config, std::uint64_t seed,
                std::uint64_t common_seed = 0);

  /// Produces the fix of the epoch at `truth.t`, advancing the error processes by `dt_s`
  /// (the time since the previous call). `utc` is the epoch's UTC instant. The fix type,
  /// DOPs and satellite count are left for the caller (they come from the constellation).
  GnssFix Calc(const TruthSample& truth, UnixTime utc, double dt_s, const ErrorInputs& in = {});

  /// Current position error of the antenna in ENU (m), for diagnostics and tests.
  const Eigen::Vector3d& position_error_N_m() const { return err_N_m_; }
  const ReceiverModelConfig& config() const { return config_; }

 private:
  void Advance(Eigen::Vector3d& state, std::mt19937_64& rng,
               std::normal_distribution<double>& normal, double phi, bool first);
  ReceiverModelConfig config_;
  std::mt19937_64 rng_, common_rng_;
  // one distribution per engine: a normal distribution caches its second variate, so sharing one
  // between the engines would leak the common stream into this receiver's own stream
  std::normal_distribution<double> normal_{0.0, 1.0}, common_normal_{0.0, 1.0};
  Eigen::Vector3d own_ = Eigen::Vector3d::Zero(), common_ = Eigen::Vector3d::Zero(),
                  burst_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d err_N_m_ = Eigen::Vector3d::Zero();
  bool started_ = false;
};

}  // namespace hil::gnss

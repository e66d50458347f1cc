#pragma once
/// @file
/// @system
/// name: RoverRtk (an F9-class rover's RTK state, driven by the corrections it receives)
/// input: the times at which the rover received a base observation message (an MSM whose CRC
///        passed, the base position known from 1005/1006); at each navigation epoch: whether the
///        rover has a standalone 3-D fix, the baseline length
/// output: the RTK state (none, float, fixed), the age of the corrections, the position error
///         of the state (ENU) and the 1-sigma accuracy the receiver reports for it
/// rate: the navigation rate
/// @endsystem
///
/// The timeline, with the age of the corrections a = t − (last observation message received):
///  - no corrections, or a > `dgnss_timeout_s` (CFG-NAVSPG-CONSTR_DGNSSTO, default 60 s in the
///    interface description): standalone 3-D fix (carrSoln 0, GGA quality 1);
///  - a stream of corrections starts (first message with a ≤ `fixed_max_age_s` after none):
///    float `time_to_float_s` later (carrSoln 1, GGA 5);
///  - float for `time_to_fix_s` while a ≤ `fixed_max_age_s` → fixed (carrSoln 2, GGA 4), unless
///    CFG-NAVHPG-DGNSSMODE is 2 (float only). The ZED-F9P data sheet gives an RTK convergence
///    time "< 10 s" (u-blox UBX-17051259): the default 10 s is that bound; plus
///    `time_to_fix_per_km_s` per km of baseline (default 0, ours);
///  - fixed while a ≤ `fixed_max_age_s`; then float (the convergence starts over when fresh
///    corrections return); float while a ≤ `dgnss_timeout_s`, then 3-D.
/// `fixed_max_age_s` (5 s) and `time_to_float_s` (1 s) are ours: the receiver documents neither.
/// Errors: fixed, a Gauss–Markov process per axis (correlation 60 s, ours) whose horizontal CEP
/// is `fixed_cep_m` + `fixed_ppm` × baseline (data sheet: 0.01 m + 1 ppm CEP; per-axis sigma =
/// CEP / 1.1774), vertical 1.5 × the horizontal sigma (ours); float, the same process scaled to a
/// sigma converging from `float_sigma_start_m` to `float_sigma_end_m` with time constant
/// `float_convergence_s` (1 m, 0.1 m, 20 s: ours). Every draw comes from this object's own seeded
/// stream, one per axis each epoch whatever the state.
/// Wrong fixes (issue 44, Build item 2): each fix is wrong with probability
/// `wrong_fix.probability` (default 0: ours, the data sheet gives no rate), the `rtk` profile's
/// model (WrongFix: a few satellites off by whole L1 cycles, the position off by their
/// least-squares image, decimetres) added to the fixed error while the state stays fixed; when it
/// ends (its hold, or one of its satellites lost) the rover falls back to float and converges to a
/// new fix `time_to_fix_s` later. Its draws come from a second stream of its own, so the rest is
/// unchanged by the rate.

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/rtk_solution.h"
#include "hil/firmware_emu/gnss/wrong_fix.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::rtk {

struct RoverRtkConfig {
  double time_to_float_s = 1.0;
  double time_to_fix_s = 10.0;
  /// Added to time_to_fix_s per km of baseline (0: none). The decorrelation of the atmosphere
  /// between base and rover lengthens the ambiguity search; no receiver documents by how much,
  /// so the value is the scenario's (ours).
  double time_to_fix_per_km_s = 0.0;
  double fixed_max_age_s = 5.0;
  double dgnss_timeout_s = 60.0;
  bool fixed_allowed = true;  ///< CFG-NAVHPG-DGNSSMODE 3 (2: float only)
  double fixed_cep_m = 0.01, fixed_ppm = 1.0;
  double float_sigma_start_m = 1.0, float_sigma_end_m = 0.1, float_convergence_s = 20.0;
  double error_correlation_s = 60.0;
  gnss::WrongFixConfig wrong_fix;
};

struct RoverRtkEpoch {
  gnss::RtkState state = gnss::RtkState::kNone;
  double correction_age_s = -1.0;                       ///< < 0: no corrections received yet
  Eigen::Vector3d error_N_m = Eigen::Vector3d::Zero();  ///< ENU (float/fixed only)
  double sigma_h_m = 0, sigma_v_m = 0;                  ///< per-axis 1-sigma (float/fixed only)
  bool wrong_fix = false;  ///< fixed to wrong integers (error_N_m holds their offset)
};

class RoverRtk {
 public:
  RoverRtk(const RoverRtkConfig& config, std::uint64_t seed);
  /// A base observation message received at `t` (calls in increasing time).
  void OnCorrection(Time t);
  /// The epoch at `t`, `dt_s` after the previous; `valid`: standalone 3-D fix; `sats`: the sky
  /// (its used satellites are the fixable ones of a wrong fix; none: no wrong fix).
  RoverRtkEpoch Step(Time t, double dt_s, bool valid, double baseline_m,
                     const std::vector<gnss::SatelliteView>& sats = {});
  std::uint64_t wrong_fixes() const { return wrong_fixes_; }
  RoverRtkConfig& config() { return config_; }

 private:
  double Age(Time t) const;
  void Advance(Time t, bool valid, double baseline_m);
  void WrongFixEpoch(Time t, bool fixed_now, const std::vector<gnss::SatelliteView>& sats);
  RoverRtkConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  Eigen::Vector3d unit_ = Eigen::Vector3d::Zero();  // the GM process, unit variance per axis
  gnss::RtkState state_ = gnss::RtkState::kNone;
  std::optional<Time> last_correction_, stream_start_;
  Time float_since_{}, converge_since_{};
  bool converging_ = false;
  bool started_ = false;
  std::mt19937_64 wrong_rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  gnss::WrongFix wrong_;
  std::uint64_t wrong_fixes_ = 0;
};

}  // namespace hil::rtk

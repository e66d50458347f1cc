#pragma once
/// @file
/// @system
/// name: RtkSolution (float/fixed ambiguity state of the `rtk` profile's rough mode)
/// input: at each navigation epoch: whether the receiver has a fix, the satellites (used, NLOS)
/// output: RTK state (float or fixed), the position error of the state (float error; a wrong
///         fix's offset), the accuracy the receiver reports for it
/// rate: the navigation rate
/// @endsystem
///
/// After each (re)acquisition the solution is float for `time_to_fix_s` (+ a uniform draw in
/// [0, `time_to_fix_spread_s`]): its error is a Gauss–Markov process (correlation
/// `float_correlation_s`) whose sigma converges from `float_sigma_m` to
/// `float_converged_sigma_m` with time constant `float_convergence_s` (vertical 1.5 ×). Then the
/// ambiguities are fixed, provided at least `min_sats_fixed` satellites are used in line of sight
/// with C/N0 ≥ `fix_min_dbhz` (NLOS satellites carry no fixable carrier); the float error vanishes
/// at once: the position jumps by it. With fewer such satellites a fixed solution falls back to
/// float and re-fixes `refix_s` after they return. Each fix is wrong with probability
/// `wrong_fix_probability` (WrongFix, wrong_fix.h: `wrong_fix_satellites` used satellites off by
/// ±1…±`wrong_fix_cycles` L1 cycles), while the receiver reports a fixed solution with its
/// centimetre accuracy; when it ends the solution re-fixes through float. Every draw comes from
/// this object's own seeded stream.

#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/wrong_fix.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::gnss {

/// Scenario parameters of the rough RTK (section `gnss.rtk`; defaults in the README).
struct RtkRoughness {
  double time_to_fix_s = 20.0, time_to_fix_spread_s = 0.0, refix_s = 5.0;
  double float_sigma_m = 0.3, float_converged_sigma_m = 0.05, float_convergence_s = 30.0;
  double float_correlation_s = 10.0;
  int min_sats_fixed = 6;
  double fix_min_dbhz = 0.0;  ///< a satellite's carrier counts for the fix from this C/N0 up
  double wrong_fix_probability = 0.0;
  double wrong_fix_hold_s = 30.0;
  int wrong_fix_satellites = 2;
  int wrong_fix_cycles = 1;
};

enum class RtkState { kNone, kFloat, kFixed };

struct RtkEpoch {
  RtkState state = RtkState::kNone;
  bool wrong_fix = false;
  Eigen::Vector3d error_N_m = Eigen::Vector3d::Zero();  ///< ENU error of the state
  double sigma_h_m = 0, sigma_v_m = 0;  ///< what the receiver adds to its accuracy (float only)
};

class RtkSolution {
 public:
  RtkSolution(const RtkRoughness& config, std::uint64_t seed);
  /// One epoch at `t`, `dt_s` after the previous; `valid`: the receiver has a fix.
  RtkEpoch Step(Time t, double dt_s, bool valid, const std::vector<SatelliteView>& sats);
  std::uint64_t wrong_fixes() const { return wrong_fixes_; }
  std::uint64_t fixes() const { return fixes_; }

 private:
  bool Fixable(const SatelliteView& s) const;
  int FixableCount(const std::vector<SatelliteView>& sats) const;
  void EnterFloat(Time t, double wait_s);
  void Fix(Time t, const std::vector<SatelliteView>& sats);
  std::vector<int> FixableSvids(const std::vector<SatelliteView>& sats) const;
  RtkRoughness config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  RtkState state_ = RtkState::kNone;
  Time t_float_{}, t_fix_allowed_{};
  Eigen::Vector3d float_unit_ = Eigen::Vector3d::Zero();
  WrongFix wrong_;
  std::uint64_t wrong_fixes_ = 0, fixes_ = 0;
};

}  // namespace hil::gnss

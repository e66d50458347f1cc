#pragma once
/// @file
/// A wrong ambiguity fix, shared by the `rtk` profile's rough RTK (RtkSolution) and the ZED-F9P
/// rover (RoverRtk): at a fix, with probability `probability`, `satellites` of the fixable
/// satellites get an integer error of ±1…±`cycles` L1 cycles each (a whole-wavelength
/// combination), and the position is off by the least-squares image of those range errors in the
/// current geometry (decimetres) while the receiver reports a fixed solution. It holds for
/// `hold_s` × a uniform draw in [0.5, 1.5] (until a residual test would catch it) or until one of
/// those satellites is lost. Draws come from the caller's stream, in a fixed order: one for the
/// probability; if wrong, three per satellite (which, how many cycles, the sign); one for the hold.

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::gnss {

struct WrongFixConfig {
  double probability = 0.0;
  double hold_s = 30.0;
  int satellites = 2;
  int cycles = 1;
};

class WrongFix {
 public:
  /// A fix at `t` over the fixable satellites `svids`: whether it is wrong (then active()).
  bool Draw(Time t, std::vector<int> svids, const WrongFixConfig& config, std::mt19937_64& rng,
            std::uniform_real_distribution<double>& uniform);
  bool active() const { return !bias_m_.empty(); }
  /// The wrong fix ends at `t`: its hold is over, or a satellite of it is not in `fixable_svids`.
  bool Ends(Time t, const std::vector<int>& fixable_svids) const;
  /// The position error (ENU, m) of the wrong integers in the geometry of `sats`.
  Eigen::Vector3d Offset(const std::vector<SatelliteView>& sats) const;
  void Clear() { bias_m_.clear(); }

 private:
  std::vector<std::pair<int, double>> bias_m_;  // svid, range error
  Time until_{};
};

}  // namespace hil::gnss

#include "hil/firmware_emu/gnss/wrong_fix.h"

#include <algorithm>

#include "hil/firmware_emu/gnss/sky_shading.h"

namespace hil::gnss {

bool WrongFix::Draw(Time t, std::vector<int> svids, const WrongFixConfig& config,
                    std::mt19937_64& rng, std::uniform_real_distribution<double>& uniform) {
  bias_m_.clear();
  if (uniform(rng) >= config.probability) return false;
  const int n = std::min(config.satellites, static_cast<int>(svids.size()));
  for (int k = 0; k < n; ++k) {
    // a partial Fisher–Yates draw: satellite k of the wrong combination
    const auto left = static_cast<double>(svids.size() - static_cast<std::size_t>(k));
    const std::size_t j =
        static_cast<std::size_t>(k) + std::min(static_cast<std::size_t>(uniform(rng) * left),
                                               svids.size() - static_cast<std::size_t>(k) - 1);
    std::swap(svids[static_cast<std::size_t>(k)], svids[j]);
    const int cycles =
        1 + std::min(static_cast<int>(uniform(rng) * config.cycles), config.cycles - 1);
    const double sign = uniform(rng) < 0.5 ? -1.0 : 1.0;
    bias_m_.emplace_back(svids[static_cast<std::size_t>(k)], sign * cycles * kGpsL1Wavelength_m);
  }
  until_ = t + DurationFromSeconds(config.hold_s * (0.5 + uniform(rng)));
  return true;
}

bool WrongFix::Ends(Time t, const std::vector<int>& fixable_svids) const {
  if (t >= until_) return true;
  return std::any_of(bias_m_.begin(), bias_m_.end(), [&](const auto& b) {
    return std::find(fixable_svids.begin(), fixable_svids.end(), b.first) == fixable_svids.end();
  });
}

Eigen::Vector3d WrongFix::Offset(const std::vector<SatelliteView>& sats) const {
  std::vector<double> err(sats.size(), 0.0);
  for (std::size_t i = 0; i < sats.size(); ++i) {
    for (const auto& [svid, bias_m] : bias_m_) {
      if (sats[i].svid == svid && !sats[i].sbas) err[i] = bias_m;
    }
  }
  const RangeErrorSolution sol = SolveRangeErrors(sats, err);
  return sol.valid ? sol.dp_N_m : Eigen::Vector3d::Zero();
}

}  // namespace hil::gnss

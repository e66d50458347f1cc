#include "hil/firmware_emu/gnss/rtk_solution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/gnss/sky_shading.h"

namespace hil::gnss {
namespace {

constexpr double kFloatVerticalFactor = 1.5;  // float height error over the per-axis horizontal

}  // namespace

bool RtkSolution::Fixable(const SatelliteView& s) const {
  return s.used && !s.sbas && !s.nlos && s.cno_dbhz >= config_.fix_min_dbhz;
}

int RtkSolution::FixableCount(const std::vector<SatelliteView>& sats) const {
  return static_cast<int>(
      std::count_if(sats.begin(), sats.end(), [this](const auto& s) { return Fixable(s); }));
}

RtkSolution::RtkSolution(const RtkRoughness& config, std::uint64_t seed)
    : config_(config), rng_(seed) {}

void RtkSolution::EnterFloat(Time t, double wait_s) {
  state_ = RtkState::kFloat;
  t_float_ = t;
  t_fix_allowed_ = t + DurationFromSeconds(wait_s);
  for (int i = 0; i < 3; ++i) float_unit_[i] = normal_(rng_);
  wrong_bias_m_.clear();
}

void RtkSolution::Fix(Time t, const std::vector<SatelliteView>& sats) {
  state_ = RtkState::kFixed;
  ++fixes_;
  if (uniform_(rng_) >= config_.wrong_fix_probability) return;
  ++wrong_fixes_;
  std::vector<int> svids;
  for (const auto& s : sats) {
    if (Fixable(s)) svids.push_back(s.svid);
  }
  const int n = std::min(config_.wrong_fix_satellites, static_cast<int>(svids.size()));
  for (int k = 0; k < n; ++k) {
    // a partial Fisher–Yates draw: satellite k of the wrong combination
    const auto left = static_cast<double>(svids.size() - static_cast<std::size_t>(k));
    const std::size_t j =
        static_cast<std::size_t>(k) + std::min(static_cast<std::size_t>(uniform_(rng_) * left),
                                               svids.size() - static_cast<std::size_t>(k) - 1);
    std::swap(svids[static_cast<std::size_t>(k)], svids[j]);
    const int cycles = 1 + std::min(static_cast<int>(uniform_(rng_) * config_.wrong_fix_cycles),
                                    config_.wrong_fix_cycles - 1);
    const double sign = uniform_(rng_) < 0.5 ? -1.0 : 1.0;
    wrong_bias_m_.emplace_back(svids[static_cast<std::size_t>(k)],
                               sign * cycles * kGpsL1Wavelength_m);
  }
  t_wrong_until_ = t + DurationFromSeconds(config_.wrong_fix_hold_s * (0.5 + uniform_(rng_)));
}

Eigen::Vector3d RtkSolution::WrongOffset(const std::vector<SatelliteView>& sats) const {
  std::vector<double> err(sats.size(), 0.0);
  for (std::size_t i = 0; i < sats.size(); ++i) {
    for (const auto& [svid, bias_m] : wrong_bias_m_) {
      if (sats[i].svid == svid && !sats[i].sbas) err[i] = bias_m;
    }
  }
  const RangeErrorSolution sol = SolveRangeErrors(sats, err);
  return sol.valid ? sol.dp_N_m : Eigen::Vector3d::Zero();
}

RtkEpoch RtkSolution::Step(Time t, double dt_s, bool valid,
                           const std::vector<SatelliteView>& sats) {
  if (!valid) {
    state_ = RtkState::kNone;
    wrong_bias_m_.clear();
    return {};
  }
  const int fixable = FixableCount(sats);
  if (state_ == RtkState::kNone) {
    EnterFloat(t, config_.time_to_fix_s + config_.time_to_fix_spread_s * uniform_(rng_));
  } else if (state_ == RtkState::kFixed) {
    bool lost = fixable < config_.min_sats_fixed;
    if (!wrong_bias_m_.empty()) {
      lost = lost || t >= t_wrong_until_;
      for (const auto& [svid, bias_m] : wrong_bias_m_) {
        lost = lost || std::none_of(sats.begin(), sats.end(), [this, svid = svid](const auto& s) {
                 return s.svid == svid && Fixable(s);
               });
      }
    }
    if (lost) EnterFloat(t, config_.refix_s);
  } else {
    const double phi = std::exp(-dt_s / config_.float_correlation_s);
    const double q = std::sqrt(1.0 - phi * phi);
    for (int i = 0; i < 3; ++i) float_unit_[i] = phi * float_unit_[i] + q * normal_(rng_);
  }
  if (state_ == RtkState::kFloat && t >= t_fix_allowed_ && fixable >= config_.min_sats_fixed)
    Fix(t, sats);

  RtkEpoch out;
  out.state = state_;
  if (state_ == RtkState::kFloat) {
    const double c = config_.float_converged_sigma_m;
    const double sigma = c + (config_.float_sigma_m - c) *
                                 std::exp(-ToSeconds(t - t_float_) / config_.float_convergence_s);
    out.error_N_m = sigma * Eigen::Vector3d(float_unit_.x(), float_unit_.y(),
                                            kFloatVerticalFactor * float_unit_.z());
    out.sigma_h_m = sigma * std::numbers::sqrt2;
    out.sigma_v_m = sigma * kFloatVerticalFactor;
  } else if (!wrong_bias_m_.empty()) {
    out.wrong_fix = true;
    out.error_N_m = WrongOffset(sats);
  }
  return out;
}

}  // namespace hil::gnss

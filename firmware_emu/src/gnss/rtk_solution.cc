#include "hil/firmware_emu/gnss/rtk_solution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  wrong_.Clear();
}

std::vector<int> RtkSolution::FixableSvids(const std::vector<SatelliteView>& sats) const {
  std::vector<int> svids;
  for (const auto& s : sats) {
    if (Fixable(s)) svids.push_back(s.svid);
  }
  return svids;
}

void RtkSolution::Fix(Time t, const std::vector<SatelliteView>& sats) {
  state_ = RtkState::kFixed;
  ++fixes_;
  const WrongFixConfig wrong{config_.wrong_fix_probability, config_.wrong_fix_hold_s,
                             config_.wrong_fix_satellites, config_.wrong_fix_cycles};
  if (wrong_.Draw(t, FixableSvids(sats), wrong, rng_, uniform_)) ++wrong_fixes_;
}

RtkEpoch RtkSolution::Step(Time t, double dt_s, bool valid,
                           const std::vector<SatelliteView>& sats) {
  if (!valid) {
    state_ = RtkState::kNone;
    wrong_.Clear();
    return {};
  }
  const int fixable = FixableCount(sats);
  if (state_ == RtkState::kNone) {
    EnterFloat(t, config_.time_to_fix_s + config_.time_to_fix_spread_s * uniform_(rng_));
  } else if (state_ == RtkState::kFixed) {
    bool lost = fixable < config_.min_sats_fixed;
    if (wrong_.active()) lost = lost || wrong_.Ends(t, FixableSvids(sats));
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
  } else if (wrong_.active()) {
    out.wrong_fix = true;
    out.error_N_m = wrong_.Offset(sats);
  }
  return out;
}

}  // namespace hil::gnss

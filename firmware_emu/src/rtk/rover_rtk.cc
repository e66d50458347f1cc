#include "hil/firmware_emu/rtk/rover_rtk.h"

#include <cmath>

namespace hil::rtk {
namespace {

constexpr double kRoverCepPerSigma = 1.1774;  // CEP of a circular normal over its per-axis sigma
constexpr double kRoverVerticalFactor = 1.5;  // ours
constexpr double kMicro = 1e-6;

}  // namespace

RoverRtk::RoverRtk(const RoverRtkConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed ^ 0x524F564552ULL), wrong_rng_(seed ^ 0x57524F4E47ULL) {}

void RoverRtk::WrongFixEpoch(Time t, bool fixed_now, const std::vector<gnss::SatelliteView>& sats) {
  if (state_ != gnss::RtkState::kFixed) {
    wrong_.Clear();
    return;
  }
  std::vector<int> svids;
  for (const auto& s : sats) {
    if (s.used && !s.sbas && !s.nlos) svids.push_back(s.svid);
  }
  if (fixed_now) {
    if (wrong_.Draw(t, svids, config_.wrong_fix, wrong_rng_, uniform_)) ++wrong_fixes_;
    return;
  }
  if (!wrong_.active() || !wrong_.Ends(t, svids)) return;
  // a residual test catches the wrong integers: float, and a new convergence
  wrong_.Clear();
  state_ = gnss::RtkState::kFloat;  // its float error the converged one (float_since_ kept)
  converging_ = true;
  converge_since_ = t;
}

void RoverRtk::OnCorrection(Time t) {
  // a stream starts when corrections arrive after none or after a gap longer than the fixed limit
  if (!last_correction_ || ToSeconds(t - *last_correction_) > config_.fixed_max_age_s)
    stream_start_ = t;
  last_correction_ = t;
}

double RoverRtk::Age(Time t) const {
  return last_correction_ ? ToSeconds(t - *last_correction_) : -1.0;
}

void RoverRtk::Advance(Time t, bool valid, double baseline_m) {
  using gnss::RtkState;
  const double age = Age(t);
  const bool any = age >= 0 && age <= config_.dgnss_timeout_s;
  const bool fresh = age >= 0 && age <= config_.fixed_max_age_s;
  if (!valid || !any) {
    state_ = RtkState::kNone;
    converging_ = false;
    return;
  }
  if (state_ == RtkState::kNone) {
    if (!fresh || ToSeconds(t - *stream_start_) < config_.time_to_float_s) return;
    state_ = RtkState::kFloat;
    float_since_ = t;
  }
  if (state_ == RtkState::kFixed && !fresh) state_ = RtkState::kFloat;
  if (state_ != RtkState::kFloat) return;
  if (!fresh) {
    converging_ = false;
    return;
  }
  if (!converging_) {
    converging_ = true;
    converge_since_ = t;
  }
  const double time_to_fix_s =
      config_.time_to_fix_s + config_.time_to_fix_per_km_s * baseline_m / 1000.0;
  if (config_.fixed_allowed && ToSeconds(t - converge_since_) >= time_to_fix_s) {
    state_ = RtkState::kFixed;
    converging_ = false;
  }
}

RoverRtkEpoch RoverRtk::Step(Time t, double dt_s, bool valid, double baseline_m,
                             const std::vector<gnss::SatelliteView>& sats) {
  const double phi = started_ ? std::exp(-dt_s / config_.error_correlation_s) : 0.0;
  const double q = std::sqrt(1.0 - phi * phi);
  for (int i = 0; i < 3; ++i) unit_[i] = phi * unit_[i] + q * normal_(rng_);
  started_ = true;
  const bool was_fixed = state_ == gnss::RtkState::kFixed;
  Advance(t, valid, baseline_m);
  if (config_.wrong_fix.probability > 0)
    WrongFixEpoch(t, !was_fixed && state_ == gnss::RtkState::kFixed, sats);
  RoverRtkEpoch out;
  out.state = state_;
  out.correction_age_s = Age(t);
  double sigma = 0;
  if (state_ == gnss::RtkState::kFixed) {
    sigma = (config_.fixed_cep_m + config_.fixed_ppm * kMicro * baseline_m) / kRoverCepPerSigma;
  } else if (state_ == gnss::RtkState::kFloat) {
    const double e = config_.float_sigma_end_m;
    sigma = e + (config_.float_sigma_start_m - e) *
                    std::exp(-ToSeconds(t - float_since_) / config_.float_convergence_s);
  } else {
    return out;
  }
  out.sigma_h_m = sigma;
  out.sigma_v_m = kRoverVerticalFactor * sigma;
  out.error_N_m = Eigen::Vector3d(sigma * unit_.x(), sigma * unit_.y(), out.sigma_v_m * unit_.z());
  if (wrong_.active()) {
    out.wrong_fix = true;
    out.error_N_m += wrong_.Offset(sats);
  }
  return out;
}

}  // namespace hil::rtk

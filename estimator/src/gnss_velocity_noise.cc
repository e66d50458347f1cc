#include "hil/estimator/gnss_velocity_noise.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator {

double GnssVelocityNoise::DopScale(double hdop) {
  return hdop > 0 && std::isfinite(hdop) ? std::clamp(hdop, 0.5, 20.0) : 1.0;
}

void GnssVelocityNoise::AddIncrement(double d_e_mps, double d_n_mps, double configured_std_mps,
                                     double hdop) {
  if (!params_.enabled || !std::isfinite(d_e_mps) || !std::isfinite(d_n_mps) ||
      !(configured_std_mps > 0))
    return;
  const double dop = DopScale(hdop);
  const double r2 = configured_std_mps * configured_std_mps;
  if (weight_ == 0) {
    // the configured σ as the prior, worth prior_updates updates: the estimate leaves it gradually
    sum_ = params_.prior_updates * r2 / (dop * dop);
    weight_ = params_.prior_updates;
  }
  const double keep = 1.0 - 1.0 / std::max(params_.memory_updates, 1.0);
  const double c2 = params_.clip_sigma * params_.clip_sigma;
  for (const double di : {d_e_mps, d_n_mps}) {
    // d²/2 (E[d²] = 2R for white errors), a glitch's clipped at clip_sigma of the configured model
    const double sample = std::min(0.5 * di * di, c2 * r2);
    // each axis half an update's weight (the prior counts in updates)
    sum_ = keep * sum_ + 0.5 * sample / (dop * dop);
    weight_ = keep * weight_ + 0.5;
  }
  ++updates_;
}

void GnssVelocityNoise::AddIncrementLag(double d_e_mps, double d_n_mps, double prev_d_e_mps,
                                        double prev_d_n_mps, double configured_std_mps) {
  if (!params_.enabled || !std::isfinite(d_e_mps) || !std::isfinite(d_n_mps) ||
      !std::isfinite(prev_d_e_mps) || !std::isfinite(prev_d_n_mps) || !(configured_std_mps > 0))
    return;
  const double r2 = configured_std_mps * configured_std_mps;
  if (!lag_started_) {
    // the prior: white errors of the configured σ (E[d²] = 2R, E[d_k d_k−1] = −R per axis),
    // worth prior_updates pairs
    lag0_ = params_.prior_updates * 2.0 * r2;
    lag1_ = -params_.prior_updates * r2;
    lag_started_ = true;
  }
  // a pair is clipped at clip_sigma of the configured model, as Add's innovations (a glitch or a
  // turn's INS error must not decide the ratio)
  const double cap = params_.clip_sigma * params_.clip_sigma * 2.0 * r2;
  const double keep = 1.0 - 1.0 / std::max(params_.memory_updates, 1.0);
  const double d[2] = {d_e_mps, d_n_mps}, p[2] = {prev_d_e_mps, prev_d_n_mps};
  for (int i = 0; i < 2; ++i) {
    const double di = std::clamp(d[i], -std::sqrt(cap), std::sqrt(cap));
    const double pi = std::clamp(p[i], -std::sqrt(cap), std::sqrt(cap));
    lag0_ = keep * lag0_ + 0.5 * (di * di + pi * pi);
    lag1_ = keep * lag1_ + di * pi;
  }
}

double GnssVelocityNoise::one_minus_rho() const {
  if (!lag_started_ || !(lag0_ > 0)) return 1.0;
  return std::clamp(-2.0 * lag1_ / lag0_, 0.0, 2.0);
}

double GnssVelocityNoise::std_at_hdop1_mps() const {
  if (!params_.enabled || updates_ < params_.min_updates || !(weight_ > 0)) return 0.0;
  const double k = one_minus_rho();
  if (k < params_.min_one_minus_rho) return 0.0;  // too correlated to learn from increments
  // white increments (k = 1) as before; a correlated error's variance is the increments' / k
  return std::sqrt(std::max(sum_ / weight_, 0.0) / std::min(k, 1.0));
}

double GnssVelocityNoise::Std(double configured_std_mps, double hdop, double floor_mps) const {
  if (!params_.enabled || updates_ < params_.min_updates) return configured_std_mps;
  const double at_hdop1 = std_at_hdop1_mps();
  if (at_hdop1 <= 0) return configured_std_mps;  // nothing learned (too correlated)
  const double learned = at_hdop1 * DopScale(hdop);
  return std::min(configured_std_mps, std::max(learned, floor_mps));
}

}  // namespace hil::estimator

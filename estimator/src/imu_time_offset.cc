// IMU tag lag from GNSS course increments against gyro heading increments (imu_time_offset.h).
#include "hil/estimator/imu_time_offset.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator {

namespace {
std::int64_t SecondsToNs(double s) { return static_cast<std::int64_t>(std::llround(s * 1e9)); }
}  // namespace

ImuTimeOffset::ImuTimeOffset(const ImuTimeOffsetParams& params) : params_(params) {
  const double span = params_.max_lag_s - params_.min_lag_s;
  n_ =
      params_.step_s > 0 && span > 0
          ? std::min(kMaxCandidates, static_cast<int>(std::floor(span / params_.step_s + 1e-9)) + 1)
          : 0;
}

void ImuTimeOffset::AddImu(GpsTime t, double heading_increment_rad) {
  if (!params_.enabled || n_ < 3 || !std::isfinite(heading_increment_rad)) return;
  const std::int64_t t_ns = ToNs(t);
  if (!history_.empty() && t_ns <= history_.back().t_ns) return;
  const double psi_before = psi_rad_;
  psi_rad_ += heading_increment_rad;
  double area = 0.0;
  if (!history_.empty()) {
    const Heading& last = history_.back();
    area =
        last.area_rad_s + 0.5e-9 * static_cast<double>(t_ns - last.t_ns) * (psi_before + psi_rad_);
  }
  history_.Push({t_ns, psi_rad_, area});
  // the pending fixes whose every candidate the history now covers
  const std::int64_t reach_ns = SecondsToNs(params_.max_lag_s + params_.rate_half_window_s +
                                            0.5 * std::max(params_.heading_window_s, 0.0));
  while (!pending_.empty() && pending_.front().t_ns + reach_ns <= t_ns) {
    const Course c = pending_.front();
    pending_.PopFront();
    Use(c);
  }
}

void ImuTimeOffset::AddVelocity(GpsTime t, double v_east_mps, double v_north_mps, double std_mps) {
  if (!params_.enabled || n_ < 3) return;
  const double speed = std::hypot(v_east_mps, v_north_mps);
  const std::int64_t t_ns = ToNs(t);
  if (!std::isfinite(speed) || !(std_mps > 0) || !std::isfinite(std_mps)) return;
  if (!pending_.empty() && t_ns <= pending_.back().t_ns) return;
  if (speed < params_.min_speed_mps) {
    prev_.reset();  // no course here: the next increment starts at the next fix with one
    return;
  }
  const double sigma_chi = std_mps / speed;
  pending_.Push({t_ns, std::atan2(v_north_mps, v_east_mps), sigma_chi * sigma_chi, speed});
}

std::optional<ImuTimeOffset::Heading> ImuTimeOffset::HeadingAt(std::int64_t t_ns) const {
  const std::size_t n = history_.size();
  if (n < 2 || t_ns < history_.front().t_ns || t_ns > history_.back().t_ns) return std::nullopt;
  // the first entry at or after t (binary search over the ring's time-ordered entries)
  std::size_t lo = 0, hi = n - 1;
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (history_[mid].t_ns < t_ns) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  if (lo == 0) return history_[0];
  const Heading& a = history_[lo - 1];
  const Heading& b = history_[lo];
  const double w = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  const double psi = a.psi_rad + w * (b.psi_rad - a.psi_rad);
  return Heading{t_ns, psi,
                 a.area_rad_s + 0.5e-9 * static_cast<double>(t_ns - a.t_ns) * (a.psi_rad + psi)};
}

std::optional<double> ImuTimeOffset::MeanHeadingAt(std::int64_t t_ns) const {
  const std::int64_t half_ns = SecondsToNs(0.5 * params_.heading_window_s);
  if (half_ns <= 0) {
    const std::optional<Heading> h = HeadingAt(t_ns);
    return h ? std::optional<double>(h->psi_rad) : std::nullopt;
  }
  const std::optional<Heading> a = HeadingAt(t_ns - half_ns);
  const std::optional<Heading> b = HeadingAt(t_ns + half_ns);
  if (!a || !b) return std::nullopt;
  return (b->area_rad_s - a->area_rad_s) / (2e-9 * static_cast<double>(half_ns));
}

std::optional<double> ImuTimeOffset::PredictedCourse(std::int64_t t_ns, std::int64_t lag_ns,
                                                     double speed_mps) const {
  const std::int64_t h_ns = SecondsToNs(params_.rate_half_window_s);
  // the heading without the ride's shaking (heading_window_s)
  const std::optional<double> psi = MeanHeadingAt(t_ns + lag_ns);
  const std::optional<double> before = MeanHeadingAt(t_ns + lag_ns - h_ns);
  const std::optional<double> after = MeanHeadingAt(t_ns + lag_ns + h_ns);
  if (!psi || !before || !after || h_ns <= 0) return std::nullopt;
  const double w = (*after - *before) / (2e-9 * static_cast<double>(h_ns));
  return *psi + std::atan2(w * lever_x_m_, speed_mps - w * lever_y_m_);
}

void ImuTimeOffset::Use(const Course& c) {
  // pairs about pair_interval apart (1 ms of jitter allowed), not overlapping
  if (prev_ && c.t_ns - prev_->t_ns < SecondsToNs(params_.pair_interval_s) - 1'000'000) return;
  const std::optional<Course> prev = prev_;
  prev_ = c;
  if (!prev || c.t_ns - prev->t_ns > params_.max_fix_interval.count()) return;
  const double d_chi = std::remainder(c.chi_rad - prev->chi_rad, 2.0 * M_PI);
  const double var =
      prev->var_rad2 + c.var_rad2 + params_.course_floor_rad * params_.course_floor_rad;
  std::array<double, kMaxCandidates> r2{};
  for (int j = 0; j < n_; ++j) {
    const std::int64_t lag_ns = SecondsToNs(params_.min_lag_s + j * params_.step_s);
    const std::optional<double> a = PredictedCourse(prev->t_ns, lag_ns, prev->speed_mps);
    const std::optional<double> b = PredictedCourse(c.t_ns, lag_ns, c.speed_mps);
    if (!a || !b) return;  // the history does not cover every candidate: not used
    const double r = d_chi - (*b - *a);
    r2[j] = r * r / var;
  }
  const double decay =
      std::exp(-1e-9 * static_cast<double>(c.t_ns - prev->t_ns) / params_.memory_s);
  for (int j = 0; j < n_; ++j) cost_[j] = cost_[j] * decay + r2[j];
  pairs_ = pairs_ * decay + 1.0;
  ++increments_;
  Estimate();
}

void ImuTimeOffset::Estimate() {
  int best = 0;
  for (int j = 1; j < n_; ++j) {
    if (cost_[j] < cost_[best]) best = j;
  }
  conclusive_ = false;
  if (best == 0 || best == n_ - 1) {
    lag_s_ = params_.min_lag_s + best * params_.step_s;
    lag_std_s_ = params_.max_lag_s - params_.min_lag_s;
    evidence_ = 0;
    return;  // at the grid's edge: no minimum inside it
  }
  // parabola through the minimum and its neighbours: vertex and curvature
  const double jm = cost_[best - 1], j0 = cost_[best], jp = cost_[best + 1];
  const double curv = jm - 2.0 * j0 + jp;
  const double shift = curv > 0 ? std::clamp(0.5 * (jm - jp) / curv, -0.5, 0.5) : 0.0;
  lag_s_ = params_.min_lag_s + (best + shift) * params_.step_s;
  const double h = params_.step_s;
  const double j_min = curv > 0 ? j0 - 0.125 * (jm - jp) * (jm - jp) / curv : j0;
  // the residuals' own scale (the a-posteriori variance factor of least squares): a receiver's
  // velocity σ is often quoted pessimistically (navd's NMEA default 0.2 m/s), sometimes the
  // other way; at least 0.01 so that a few noise-free pairs cannot decide
  const double scale = pairs_ > 2.0 ? std::max(j_min / (pairs_ - 1.0), 0.01) : 1.0;
  // J(L) ≈ J_min + ½ J'' (L − L̂)², J / scale a −2 log-likelihood: σ² = 2 scale / J''
  lag_std_s_ =
      curv > 0 ? std::sqrt(2.0 * scale * h * h / curv) : params_.max_lag_s - params_.min_lag_s;
  // J at zero lag: the grid point there (or its nearest)
  const int zero = std::clamp(static_cast<int>(std::lround(-params_.min_lag_s / h)), 0, n_ - 1);
  evidence_ = (cost_[zero] - j_min) / scale;
  conclusive_ = evidence_ >= params_.evidence && lag_std_s_ <= params_.max_std_s;
}

}  // namespace hil::estimator

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
  psi_rad_ += heading_increment_rad;
  history_.Push({t_ns, psi_rad_});
  // the pending fixes whose every candidate the history now covers
  const std::int64_t reach_ns = SecondsToNs(params_.max_lag_s + params_.rate_half_window_s);
  // (a window's fixes are each covered in turn: its mean is taken once its last one is)
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

std::optional<double> ImuTimeOffset::HeadingAt(std::int64_t t_ns, std::size_t& from) const {
  const std::size_t n = history_.size();
  if (n < 2 || t_ns < history_.front().t_ns || t_ns > history_.back().t_ns) return std::nullopt;
  // the first entry at or after t: a binary search over the ring's time-ordered entries, or a walk
  // on from an earlier time's entry (the candidates' times are 5 ms apart, the samples 10 ms)
  std::size_t lo = from;
  if (lo >= n) {
    std::size_t hi = n - 1;
    lo = 0;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (history_[mid].t_ns < t_ns) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
  }
  while (history_[lo].t_ns < t_ns) ++lo;
  from = lo;
  if (lo == 0) return history_[0].psi_rad;
  const Heading& a = history_[lo - 1];
  const Heading& b = history_[lo];
  const double w = static_cast<double>(t_ns - a.t_ns) / static_cast<double>(b.t_ns - a.t_ns);
  return a.psi_rad + w * (b.psi_rad - a.psi_rad);
}

std::optional<double> ImuTimeOffset::PredictedCourse(std::int64_t t_ns, std::int64_t lag_ns,
                                                     std::int64_t h_ns, double speed_mps,
                                                     std::array<std::size_t, 3>& from) const {
  const std::optional<double> psi = HeadingAt(t_ns + lag_ns, from[1]);
  const std::optional<double> before = HeadingAt(t_ns + lag_ns - h_ns, from[0]);
  const std::optional<double> after = HeadingAt(t_ns + lag_ns + h_ns, from[2]);
  if (!psi || !before || !after || h_ns <= 0) return std::nullopt;
  const double w = (*after - *before) / (2e-9 * static_cast<double>(h_ns));
  // the antenna's velocity in the body is (v − ω l_y, ω l_x) and its speed the fix's: the course
  // leads the heading by atan2(ω l_x, √(speed² − (ω l_x)²)) (with the fix's speed in place of
  // v − ω l_y it lagged by 16 mrad in a tractor's 3.5 m turns at 1 m/s: read as 0.05 s of lag)
  const double across = w * lever_x_m_;
  return *psi +
         std::atan2(across, std::sqrt(std::max(speed_mps * speed_mps - across * across, 0.0)));
}

bool ImuTimeOffset::PredictedMeanCourses(const WindowedCourse& w, Courses& out) const {
  if (w.n == 0) return false;
  // by fix, then by candidate (ascending times: each HeadingAt walks on from the last); each
  // candidate's sum still adds the fixes in their order
  std::fill(out.begin(), out.begin() + n_, 0.0);
  std::array<std::int64_t, kMaxCandidates> lag_ns{};
  for (int j = 0; j < n_; ++j) lag_ns[j] = SecondsToNs(params_.min_lag_s + j * params_.step_s);
  const std::int64_t h_ns = SecondsToNs(params_.rate_half_window_s);
  for (std::size_t i = 0; i < w.n; ++i) {
    std::array<std::size_t, 3> from = {SIZE_MAX, SIZE_MAX, SIZE_MAX};
    for (int j = 0; j < n_; ++j) {
      const std::optional<double> p =
          PredictedCourse(w.t_fix_ns[i], lag_ns[j], h_ns, w.speed_mps[i], from);
      if (!p) return false;
      out[j] += *p;
    }
  }
  for (int j = 0; j < n_; ++j) out[j] = out[j] / static_cast<double>(w.n);
  return true;
}

bool ImuTimeOffset::PredictedMeanCoursesOfPrevious(const WindowedCourse& w, Courses& out) const {
  // the history keeps a suffix of the samples: while its first is before the earliest time read
  // (strictly: at it HeadingAt takes the entry itself), every read has the same two entries
  if (w.t_ns == prev_courses_t_ns_ && lever_x_m_ == prev_courses_lever_x_m_ &&
      history_.size() >= 2 && history_.front().t_ns < prev_courses_earliest_ns_) {
    out = prev_courses_;
    return true;
  }
  return PredictedMeanCourses(w, out);
}

void ImuTimeOffset::Use(const Course& c) {
  if (!window_.empty() && c.t_ns <= window_.back().t_ns) return;
  window_.Push(c);
  const std::int64_t half_ns = SecondsToNs(0.5 * std::max(params_.course_window_s, 0.0));
  // every fix whose window is now complete (its last fix is in), in time order
  for (std::size_t i = 0; i < window_.size(); ++i) {
    if (window_[i].t_ns <= last_centre_ns_) continue;
    if (window_[i].t_ns + half_ns > c.t_ns) break;
    last_centre_ns_ = window_[i].t_ns;
    UsePair(WindowAround(i));
  }
  // the fixes no later window holds
  while (last_centre_ns_ != INT64_MIN && !window_.empty() &&
         window_.front().t_ns < last_centre_ns_ - half_ns)
    window_.PopFront();
}

ImuTimeOffset::WindowedCourse ImuTimeOffset::WindowAround(std::size_t i) const {
  const std::int64_t half_ns = SecondsToNs(0.5 * std::max(params_.course_window_s, 0.0));
  const Course& m = window_[i];
  WindowedCourse w;
  w.t_ns = m.t_ns;
  double sum_dchi = 0.0, sum_var = 0.0;
  for (std::size_t j = 0; j < window_.size() && w.n < kMaxWindowFixes; ++j) {
    const Course& f = window_[j];
    if (f.t_ns < m.t_ns - half_ns || f.t_ns > m.t_ns + half_ns) continue;
    sum_dchi += std::remainder(f.chi_rad - m.chi_rad, 2.0 * M_PI);  // unwrapped about m's
    sum_var += f.var_rad2;
    w.t_fix_ns[w.n] = f.t_ns;
    w.speed_mps[w.n] = f.speed_mps;
    ++w.n;
  }
  const double n = static_cast<double>(std::max<std::size_t>(w.n, 1));
  w.chi_rad = m.chi_rad + sum_dchi / n;
  w.var_rad2 = sum_var / (n * n);  // the mean of independent courses
  return w;
}

void ImuTimeOffset::UsePair(const WindowedCourse& c) {
  // pairs about pair_interval apart (1 ms of jitter allowed), not overlapping
  if (prev_ && c.t_ns - prev_->t_ns < SecondsToNs(params_.pair_interval_s) - 1'000'000) return;
  const std::optional<WindowedCourse> prev = prev_;
  prev_ = c;
  if (!prev || c.t_ns - prev->t_ns > params_.max_fix_interval.count()) return;
  const double d_chi = std::remainder(c.chi_rad - prev->chi_rad, 2.0 * M_PI);
  const double var =
      prev->var_rad2 + c.var_rad2 + params_.course_floor_rad * params_.course_floor_rad;
  // the history does not cover every candidate: not used
  Courses a{}, b{};
  if (!PredictedMeanCoursesOfPrevious(*prev, a) || !PredictedMeanCourses(c, b)) return;
  prev_courses_ = b;  // the next pair's first
  prev_courses_t_ns_ = c.t_ns;
  prev_courses_lever_x_m_ = lever_x_m_;
  prev_courses_earliest_ns_ = INT64_MAX;
  const std::int64_t h_ns = SecondsToNs(params_.rate_half_window_s);
  for (std::size_t i = 0; i < c.n; ++i) {
    prev_courses_earliest_ns_ =
        std::min(prev_courses_earliest_ns_, c.t_fix_ns[i] + SecondsToNs(params_.min_lag_s) - h_ns);
  }
  std::array<double, kMaxCandidates> r2{};
  for (int j = 0; j < n_; ++j) {
    const double r = d_chi - (b[j] - a[j]);
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

#include "hil/harness/datasets/imu_timing.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::harness {

ImuTickFit FitImuTicks(const std::vector<double>& tick_s, const std::vector<double>& tag_s) {
  if (tick_s.size() != tag_s.size() || tick_s.size() < 2)
    throw std::runtime_error("tick fit: need at least two tagged samples");
  ImuTickFit f;
  f.tick0_s = tick_s.front();
  const double n = static_cast<double>(tick_s.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double y0 = tag_s.front();
  for (std::size_t i = 0; i < tick_s.size(); ++i) {
    const double x = tick_s[i] - f.tick0_s, y = tag_s[i] - y0;
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double den = n * sxx - sx * sx;
  if (den <= 0) throw std::runtime_error("tick fit: ticks do not vary");
  f.scale = (n * sxy - sx * sy) / den;
  f.offset_s = y0 + (sy - f.scale * sx) / n;
  double s2 = 0;
  f.residual_min_s = 1e300;
  f.residual_max_s = -1e300;
  for (std::size_t i = 0; i < tick_s.size(); ++i) {
    const double r = tag_s[i] - f.At(tick_s[i]);
    s2 += r * r;
    f.residual_min_s = std::min(f.residual_min_s, r);
    f.residual_max_s = std::max(f.residual_max_s, r);
  }
  f.residual_rms_s = std::sqrt(s2 / n);
  return f;
}

namespace {

// cumulative integral of the rate at the sample times (trapezoid), read by linear interpolation
struct HeadingIntegral {
  const std::vector<double>& t;
  std::vector<double> c;
  HeadingIntegral(const std::vector<double>& times, const std::vector<double>& rate) : t(times) {
    c.assign(t.size(), 0.0);
    for (std::size_t i = 1; i < t.size(); ++i)
      c[i] = c[i - 1] + 0.5 * (rate[i] + rate[i - 1]) * (t[i] - t[i - 1]);
  }
  bool Covers(double x) const { return x >= t.front() && x <= t.back(); }
  double At(double x) const {
    const auto it = std::upper_bound(t.begin(), t.end(), x);
    const std::size_t j =
        std::clamp<std::size_t>(static_cast<std::size_t>(it - t.begin()), 1, t.size() - 1);
    const double a = (x - t[j - 1]) / (t[j] - t[j - 1]);
    return c[j - 1] + a * (c[j] - c[j - 1]);
  }
};

double WrapPi(double a) { return std::remainder(a, 2 * std::numbers::pi); }

struct CourseInterval {
  double t0, t1, dcourse;
};

double LagCorrelation(const HeadingIntegral& psi, const std::vector<CourseInterval>& iv,
                      double lag) {
  double sab = 0, saa = 0, sbb = 0;
  for (const CourseInterval& i : iv) {
    if (!psi.Covers(i.t0 + lag) || !psi.Covers(i.t1 + lag)) continue;
    const double a = psi.At(i.t1 + lag) - psi.At(i.t0 + lag);
    sab += a * i.dcourse, saa += a * a, sbb += i.dcourse * i.dcourse;
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : -1.0;
}

}  // namespace

ImuLagEstimate EstimateImuLag(const std::vector<double>& imu_t_s,
                              const std::vector<double>& yaw_rate_radps,
                              const std::vector<CourseEpoch>& gnss, double max_lag_s,
                              double min_speed_mps) {
  const HeadingIntegral psi(imu_t_s, yaw_rate_radps);
  std::vector<CourseInterval> iv;
  for (std::size_t k = 1; k < gnss.size(); ++k) {
    const Eigen::Vector3d &a = gnss[k - 1].v_ned_mps, &b = gnss[k].v_ned_mps;
    if (a.head<2>().norm() < min_speed_mps || b.head<2>().norm() < min_speed_mps) continue;
    iv.push_back({gnss[k - 1].t_s, gnss[k].t_s,
                  WrapPi(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()))});
  }
  if (iv.size() < 10)
    throw std::runtime_error("time offset: fewer than 10 GNSS intervals above the speed threshold");
  const int n = static_cast<int>(std::lround(max_lag_s * 1000));
  std::vector<double> r(static_cast<std::size_t>(2 * n + 1));
  std::size_t best = 0;
  for (int k = -n; k <= n; ++k) {
    r[static_cast<std::size_t>(k + n)] = LagCorrelation(psi, iv, k * 1e-3);
    if (r[static_cast<std::size_t>(k + n)] > r[best]) best = static_cast<std::size_t>(k + n);
  }
  ImuLagEstimate e;
  e.intervals = iv.size();
  e.correlation = r[best];
  e.lag_s = (static_cast<double>(best) - n) * 1e-3;
  if (best > 0 && best + 1 < r.size()) {
    const double den = r[best - 1] - 2 * r[best] + r[best + 1];
    if (den < 0) e.lag_s += 0.5e-3 * (r[best - 1] - r[best + 1]) / den;
  }
  return e;
}

}  // namespace hil::harness

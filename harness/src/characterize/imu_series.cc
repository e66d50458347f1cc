#include "hil/harness/characterize/imu_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hil::harness {

double MedianIntervalS(const ImuSeries& s) {
  if (s.size() == 0 || s.t_s.size() != s.size() + 1)
    throw std::invalid_argument("IMU series without an interval");
  std::vector<double> d(s.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = s.t_s[k + 1] - s.t_s[k];
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  return *mid;
}

UniformImu ResampleUniform(const ImuSeries& s, double step_s) {
  if (!(step_s > 0)) throw std::invalid_argument("grid step must be positive");
  if (s.size() == 0 || s.t_s.size() != s.size() + 1)
    throw std::invalid_argument("IMU series without an interval");
  const double t0 = s.t_s.front();
  const auto cells = static_cast<std::size_t>(std::floor((s.t_s.back() - t0) / step_s + 1e-9));
  if (cells == 0) throw std::invalid_argument("IMU series shorter than one grid step");
  UniformImu u;
  u.t0_s = t0;
  u.step_s = step_s;
  u.gyro_radps.reserve(cells);
  u.accel_mps2.reserve(cells);
  // each cell's mean is the overlap-weighted sum of the source intervals it covers
  std::size_t k = 0;
  for (std::size_t j = 0; j < cells; ++j) {
    const double a = t0 + static_cast<double>(j) * step_s;
    const double b = t0 + static_cast<double>(j + 1) * step_s;
    Eigen::Vector3d g = Eigen::Vector3d::Zero(), f = Eigen::Vector3d::Zero();
    while (k + 1 < s.t_s.size() && s.t_s[k + 1] <= a) ++k;
    for (std::size_t i = k; i < s.size() && s.t_s[i] < b; ++i) {
      const double w = std::min(b, s.t_s[i + 1]) - std::max(a, s.t_s[i]);
      if (w <= 0) continue;
      g += w * s.gyro_radps[i];
      f += w * s.accel_mps2[i];
      u.max_gap_s = std::max(u.max_gap_s, s.t_s[i + 1] - s.t_s[i]);
    }
    u.gyro_radps.push_back(g / step_s);
    u.accel_mps2.push_back(f / step_s);
  }
  return u;
}

UniformImu Slice(const UniformImu& u, std::size_t first, std::size_t count) {
  if (first > u.size() || count > u.size() - first)
    throw std::invalid_argument("slice outside the series");
  UniformImu o;
  o.t0_s = u.t0_s + static_cast<double>(first) * u.step_s;
  o.step_s = u.step_s;
  o.max_gap_s = u.max_gap_s;
  const auto b = static_cast<std::ptrdiff_t>(first), e = static_cast<std::ptrdiff_t>(first + count);
  o.gyro_radps.assign(u.gyro_radps.begin() + b, u.gyro_radps.begin() + e);
  o.accel_mps2.assign(u.accel_mps2.begin() + b, u.accel_mps2.begin() + e);
  return o;
}

}  // namespace hil::harness

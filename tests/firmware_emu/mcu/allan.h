#pragma once
// Overlapping Allan deviation of a uniformly sampled record (test helper).
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace hil::mcu::test {

/// {τ, σ(τ)} for cluster sizes m = 1, 2, 4, … up to n/8 samples.
inline std::vector<std::pair<double, double>> AllanDeviation(const std::vector<double>& y,
                                                             double dt) {
  const std::size_t n = y.size();
  std::vector<double> cum(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) cum[i + 1] = cum[i] + y[i];
  std::vector<std::pair<double, double>> out;
  for (std::size_t m = 1; m <= n / 8; m *= 2) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t k = 0; k + 2 * m <= n; ++k) {
      const double a = (cum[k + m] - cum[k]) / static_cast<double>(m);
      const double b = (cum[k + 2 * m] - cum[k + m]) / static_cast<double>(m);
      sum += (b - a) * (b - a);
      ++count;
    }
    out.emplace_back(static_cast<double>(m) * dt,
                     std::sqrt(sum / (2.0 * static_cast<double>(count))));
  }
  return out;
}

/// White-noise density from the first point (τ = dt): N = σ(dt)·√dt.
inline double NoiseDensityFromAllan(const std::vector<std::pair<double, double>>& a) {
  return a.front().second * std::sqrt(a.front().first);
}

/// Bias instability B: the largest Allan deviation left after removing the white part,
/// divided by √(2 ln2 / π).
inline double BiasInstabilityFromAllan(const std::vector<std::pair<double, double>>& a,
                                       double n_density) {
  double best = 0;
  for (const auto& [tau, sigma] : a) {
    const double rest = sigma * sigma - n_density * n_density / tau;
    if (rest > best) best = rest;
  }
  return std::sqrt(best) / std::sqrt(2.0 * std::log(2.0) / 3.14159265358979323846);
}

}  // namespace hil::mcu::test

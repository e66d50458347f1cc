#include "hil/harness/core/percentile.h"

#include <algorithm>
#include <cmath>

namespace hil::harness {

double PercentileOfSorted(const std::vector<double>& v, double pct) {
  if (v.empty()) return 0;
  const double pos = pct / 100.0 * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  const double f = pos - static_cast<double>(lo);
  return v[lo] * (1 - f) + v[hi] * f;
}

double Percentile(std::vector<double> v, double pct) {
  std::sort(v.begin(), v.end());
  return PercentileOfSorted(v, pct);
}

}  // namespace hil::harness

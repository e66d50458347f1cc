#include "hil/harness/characterize/allan_deviation.h"

#include <cmath>
#include <stdexcept>

namespace hil::harness {

std::vector<std::size_t> OctaveClusterSizes(std::size_t samples) {
  std::vector<std::size_t> m;
  for (std::size_t k = 1; 4 * k <= samples; k *= 2) m.push_back(k);
  return m;
}

std::vector<double> OverlappingAllanDeviation(const std::vector<double>& y, double tau0_s,
                                              const std::vector<std::size_t>& m) {
  const std::size_t n = y.size();
  double mean = 0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(n ? n : 1);
  // θ_k = τ0 Σ_{i<k} (y_i − mean), accumulated in long double
  std::vector<double> theta(n + 1, 0.0);
  long double acc = 0;
  for (std::size_t k = 0; k < n; ++k) {
    acc += static_cast<long double>(y[k] - mean);
    theta[k + 1] = static_cast<double>(acc * static_cast<long double>(tau0_s));
  }
  std::vector<double> out;
  out.reserve(m.size());
  for (std::size_t mk : m) {
    if (mk == 0 || 2 * mk > n) throw std::invalid_argument("cluster size outside the series");
    const std::size_t terms = n - 2 * mk + 1;
    long double sum = 0;
    for (std::size_t k = 0; k < terms; ++k) {
      const double d = theta[k + 2 * mk] - 2 * theta[k + mk] + theta[k];
      sum += static_cast<long double>(d) * d;
    }
    const double tau = static_cast<double>(mk) * tau0_s;
    out.push_back(std::sqrt(static_cast<double>(sum / terms) / (2 * tau * tau)));
  }
  return out;
}

}  // namespace hil::harness

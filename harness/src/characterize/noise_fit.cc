#include "hil/harness/characterize/noise_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hil::harness {
namespace {

// secant slope of log σ over log τ around point i (one-sided at the ends)
double LocalSlope(const std::vector<double>& t, const std::vector<double>& s, std::size_t i) {
  const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 < t.size() ? i + 1 : i;
  return std::log(s[b] / s[a]) / std::log(t[b] / t[a]);
}

// a rise steeper than this after the floor is read as rate random walk (+1/2); flatter ones are
// the floor's own scatter or the shoulder of a correlated bias (a choice, not a source's)
constexpr double kRandomWalkMinSlope = 0.35;

}  // namespace

NoiseTerms FitNoiseTerms(const std::vector<double>& tau_s, const std::vector<double>& adev) {
  if (tau_s.size() < 2 || tau_s.size() != adev.size())
    throw std::invalid_argument("noise fit needs at least two (tau, sigma) points");
  NoiseTerms r;
  const std::size_t n = tau_s.size();
  // past an initial rise (a tone or a filter at the shortest τ), the floor is the first local
  // minimum (where the white-noise decline ends), else the last point
  std::size_t i_start = 0;
  while (i_start + 1 < n && adev[i_start + 1] >= adev[i_start]) ++i_start;
  if (i_start + 1 == n) i_start = 0;  // a curve that only rises: no decline to skip to
  std::size_t i_min = i_start;
  while (i_min + 1 < n && adev[i_min + 1] < adev[i_min]) ++i_min;
  // white noise: slope nearest −1/2 from the decline's start to the floor
  std::size_t i_white = i_start;
  double best = 1e300;
  for (std::size_t i = i_start; i <= i_min; ++i) {
    const double d = std::abs(LocalSlope(tau_s, adev, i) + 0.5);
    if (d < best) best = d, i_white = i;
  }
  r.white = adev[i_white] * std::sqrt(tau_s[i_white]);
  r.white_tau_s = tau_s[i_white];
  r.white_slope = LocalSlope(tau_s, adev, i_white);
  // bias instability: the floor
  r.bias_instability = adev[i_min] / kBiasInstabilityFloor;
  r.bias_instability_tau_s = tau_s[i_min];
  const double last_slope =
      std::log(adev[n - 1] / adev[n - 2]) / std::log(tau_s[n - 1] / tau_s[n - 2]);
  r.bias_instability_resolved = i_min + 1 < n || last_slope > -0.25;
  // rate random walk: slope nearest +1/2 after the minimum, if it rises at all
  best = 1e300;
  for (std::size_t i = i_min + 1; i < n; ++i) {
    const double slope = LocalSlope(tau_s, adev, i);
    if (slope > kRandomWalkMinSlope && std::abs(slope - 0.5) < best) {
      best = std::abs(slope - 0.5);
      r.rate_random_walk = adev[i] * std::sqrt(3.0 / tau_s[i]);
      r.rate_random_walk_tau_s = tau_s[i];
    }
  }
  return r;
}

double WhiteNoiseFromPsd(const std::vector<double>& freq_hz, const std::vector<double>& density,
                         double f_lo_hz, double f_hi_hz) {
  std::vector<double> band;
  for (std::size_t k = 0; k < freq_hz.size() && k < density.size(); ++k)
    if (freq_hz[k] >= f_lo_hz && freq_hz[k] <= f_hi_hz) band.push_back(density[k]);
  if (band.empty()) throw std::invalid_argument("no PSD bin in the white-noise band");
  const auto mid = band.begin() + static_cast<std::ptrdiff_t>(band.size() / 2);
  std::nth_element(band.begin(), mid, band.end());
  return std::sqrt(*mid / 2.0);
}

}  // namespace hil::harness

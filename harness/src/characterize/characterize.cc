#include "hil/harness/characterize/characterize.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hil/harness/characterize/allan_deviation.h"
#include "hil/harness/characterize/welch_psd.h"

namespace hil::harness {
namespace {

constexpr std::size_t kMinSamples = 64;
// the PSD's white level is read over [fs/50, fs/10]: under any anti-alias filter's corner and the
// roll-off of held samples, above where bias instability lifts the spectrum (a choice, not a
// source's)
constexpr double kPsdBandLo = 1.0 / 50, kPsdBandHi = 1.0 / 10;

std::string Seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f", s);
  return b;
}

// the analysed cells: the window, or the longest still period inside it
std::pair<std::size_t, std::size_t> PickCells(const UniformImu& u, const CharacterizeOptions& o,
                                              const std::vector<StillPeriod>& still) {
  const double length = static_cast<double>(u.size()) * u.step_s;
  const double from = o.from_s.value_or(0), to = o.to_s.value_or(length);
  if (from < 0 || !(to > from) || from >= length)
    throw std::invalid_argument("window " + Seconds(from) + ".." + Seconds(to) +
                                " s lies outside the log (0.." + Seconds(length) + " s)");
  auto first = static_cast<std::size_t>(std::ceil(from / u.step_s - 1e-9));
  auto last = std::min(u.size(), static_cast<std::size_t>(std::floor(to / u.step_s + 1e-9)));
  if (o.still) {
    std::size_t best_first = 0, best_count = 0;
    for (const StillPeriod& p : still) {
      const std::size_t a = std::max(p.first, first), b = std::min(p.first + p.count, last);
      if (b > a && b - a > best_count) best_first = a, best_count = b - a;
    }
    if (best_count == 0)
      throw NoStillPeriod("no still period of at least " + Seconds(o.still_options.min_length_s) +
                          " s in the window");
    first = best_first;
    last = best_first + best_count;
  }
  if (last <= first || last - first < kMinSamples)
    throw std::invalid_argument("window " + Seconds(from) + ".." + Seconds(to) + " s holds " +
                                std::to_string(last > first ? last - first : 0) +
                                " samples; at least " + std::to_string(kMinSamples) + " needed");
  return {first, last - first};
}

void AnalyseAxis(const std::vector<double>& y, const Characterization& c, std::vector<double>& adev,
                 NoiseTerms& terms, std::vector<double>& psd, double& psd_white,
                 const std::vector<std::size_t>& m, std::size_t segment) {
  adev = OverlappingAllanDeviation(y, c.step_s, m);
  terms = FitNoiseTerms(c.tau_s, adev);
  const Psd p = WelchPsd(y, 1.0 / c.step_s, segment);
  psd = p.density;
  psd_white = WhiteNoiseFromPsd(p.freq_hz, p.density, c.psd_band_lo_hz, c.psd_band_hi_hz);
}

}  // namespace

Characterization Characterize(const ImuSeries& log, const CharacterizeOptions& o) {
  Characterization c;
  c.format = log.format;
  c.notes = log.notes;
  c.log_start_s = log.t_s.front();
  c.log_length_s = log.t_s.back() - log.t_s.front();
  // the median interval to the microsecond: logs on a GPS-seconds scale (~1e9 s) carry ~1e-7 s of
  // rounding in their differences
  const double step = o.step_s > 0 ? o.step_s : std::round(MedianIntervalS(log) * 1e6) / 1e6;
  const UniformImu all = ResampleUniform(log, step);
  c.step_s = all.step_s;
  c.max_gap_s = all.max_gap_s;
  c.still_periods = FindStillPeriods(all, o.still_options);
  const auto [first, count] = PickCells(all, o, c.still_periods);
  c.window = Slice(all, first, count);
  const UniformImu& u = c.window;
  c.from_s = static_cast<double>(first) * c.step_s;
  c.to_s = static_cast<double>(first + count) * c.step_s;
  c.samples = count;
  const std::vector<std::size_t> m = OctaveClusterSizes(count);
  for (std::size_t k : m) c.tau_s.push_back(static_cast<double>(k) * c.step_s);
  c.psd_segment = o.psd_segment ? o.psd_segment : DefaultWelchSegment(count);
  c.psd_band_lo_hz = kPsdBandLo / c.step_s;
  c.psd_band_hi_hz = kPsdBandHi / c.step_s;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> g(count), a(count);
    for (std::size_t i = 0; i < count; ++i) {
      g[i] = u.gyro_radps[i][axis];
      a[i] = u.accel_mps2[i][axis];
    }
    const auto ax = static_cast<std::size_t>(axis);
    for (double v : g) c.mean_gyro_radps[axis] += v / static_cast<double>(count);
    for (double v : a) c.mean_accel_mps2[axis] += v / static_cast<double>(count);
    AnalyseAxis(g, c, c.adev_gyro_radps[ax], c.gyro_terms[ax], c.psd_gyro_rad2ps2_per_hz[ax],
                c.psd_white_gyro[axis], m, c.psd_segment);
    AnalyseAxis(a, c, c.adev_accel_mps2[ax], c.accel_terms[ax], c.psd_accel_m2ps4_per_hz[ax],
                c.psd_white_accel[axis], m, c.psd_segment);
  }
  for (std::size_t k = 0; k <= c.psd_segment / 2; ++k)
    c.psd_freq_hz.push_back(static_cast<double>(k) /
                            (c.step_s * static_cast<double>(c.psd_segment)));
  c.psd_segments = (count - c.psd_segment) / (c.psd_segment / 2) + 1;
  return c;
}

}  // namespace hil::harness

#include "hil/harness/eval/outage_metrics.h"

#include <algorithm>
#include <cmath>

namespace hil::harness {
namespace {

constexpr double kStaySeconds = 2.0;
constexpr double kHorizonsS[] = {1, 2, 5, 10, 20, 30, 60};

}  // namespace

std::vector<OutageMetrics> ComputeOutages(const std::vector<ErrorSample>& errors,
                                          const FaultTimeline& faults, double reconverged_error_m) {
  // a data gap is an outage for the estimator: no GNSS reaches it
  std::vector<Fault> outages = faults.OfKind(FaultKind::kGnssOutage);
  for (const Fault& f : faults.OfKind(FaultKind::kGnssDataGap)) outages.push_back(f);
  std::stable_sort(outages.begin(), outages.end(),
                   [](const Fault& a, const Fault& b) { return a.start < b.start; });
  std::vector<OutageMetrics> out;
  for (std::size_t k = 0; k < outages.size(); ++k) {
    const Fault& f = outages[k];
    OutageMetrics m;
    m.start_s = ToSeconds(f.start);
    m.end_s = ToSeconds(f.end);
    const Time next_start = k + 1 < outages.size() ? outages[k + 1].start : Time::max();
    for (const ErrorSample& e : errors) {
      if (e.t < f.start || e.t > f.end) continue;
      ++m.samples;
      m.max_horizontal_error_m = std::max(m.max_horizontal_error_m, e.horizontal());
      m.max_abs_error_enu_m = m.max_abs_error_enu_m.cwiseMax(e.err_enu_m.cwiseAbs());
    }
    for (const double h : kHorizonsS) {
      if (h > m.end_s - m.start_s) break;
      const Time th = f.start + DurationFromSeconds(h);
      std::optional<double> latest;
      for (const ErrorSample& e : errors) {
        if (e.t >= f.start && e.t <= th) latest = e.horizontal();
      }
      if (latest) m.growth.emplace_back(h, *latest);
    }
    // reconvergence: first sample after the end from which the error stays below the threshold
    for (std::size_t i = 0; i < errors.size(); ++i) {
      const ErrorSample& e = errors[i];
      if (e.t < f.end || e.horizontal() >= reconverged_error_m) continue;
      Time stay_until = e.t + DurationFromSeconds(kStaySeconds);
      if (next_start < stay_until) stay_until = next_start;
      bool stays = true;
      for (std::size_t j = i + 1; j < errors.size() && errors[j].t <= stay_until; ++j) {
        if (errors[j].horizontal() >= reconverged_error_m) {
          stays = false;
          break;
        }
      }
      if (stays) {
        m.reconvergence_time_s = ToSeconds(e.t) - m.end_s;
        break;
      }
    }
    out.push_back(std::move(m));
  }
  return out;
}

namespace {

// Solutions missing from a gap of `gap_s` seconds: none up to 1.5 periods, else
// round(gap / period) − 1. A window edge counts like a solution, so a stream may start up to 1.5
// periods after the window opens (its phase) and end as much before it closes.
double MissingInGap(double gap_s, double period_s) {
  return gap_s > 1.5 * period_s ? std::round(gap_s / period_s) - 1 : 0.0;
}

}  // namespace

OutputTiming ComputeOutputTiming(const std::vector<EstimateRecord>& records_in, Time t_from,
                                 Time t_to, double speed) {
  OutputTiming t;
  std::vector<EstimateRecord> records;
  for (const EstimateRecord& r : records_in) {
    if (r.t_validity >= t_from && r.t_validity <= t_to) records.push_back(r);
  }
  const double window_s = ToSeconds(t_to - t_from);
  if (window_s <= 0) return t;
  t.output_rate_hz = static_cast<double>(records.size()) / window_s;
  if (records.empty()) {
    t.missing_fraction = 1.0;
    return t;
  }
  std::stable_sort(
      records.begin(), records.end(),
      [](const EstimateRecord& a, const EstimateRecord& b) { return a.t_validity < b.t_validity; });
  std::vector<double> dt_s;
  for (std::size_t i = 1; i < records.size(); ++i) {
    dt_s.push_back(ToSeconds(records[i].t_validity - records[i - 1].t_validity));
  }
  // the nominal period: the median interval (one solution alone says nothing about it)
  const double period_s = dt_s.empty() ? 0.0 : Percentile(dt_s, 50);
  if (period_s > 0) {
    double missing = MissingInGap(ToSeconds(records.front().t_validity - t_from), period_s) +
                     MissingInGap(ToSeconds(t_to - records.back().t_validity), period_s);
    for (const double d : dt_s) missing += MissingInGap(d, period_s);
    t.missing_fraction = missing / (static_cast<double>(records.size()) + missing);
  }
  std::vector<std::int64_t> wall;
  for (const auto& r : records) {
    if (r.wall_rx_ns > 0) wall.push_back(r.wall_rx_ns);
  }
  if (wall.size() >= 3) {
    std::sort(wall.begin(), wall.end());
    std::vector<double> iv_ms;
    for (std::size_t i = 1; i < wall.size(); ++i)
      iv_ms.push_back(static_cast<double>(wall[i] - wall[i - 1]) * 1e-6 * speed);
    const double med = Percentile(iv_ms, 50);
    std::vector<double> dev;
    for (const double v : iv_ms) dev.push_back(std::abs(v - med));
    t.jitter_p50_ms = Percentile(dev, 50);
    t.jitter_p99_ms = Percentile(dev, 99);
    t.jitter_max_ms = Percentile(dev, 100);
  }
  return t;
}

}  // namespace hil::harness

#include "hil/harness/eval/outage_metrics.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace hil::harness {
namespace {

constexpr double kStaySeconds = 2.0;
constexpr double kHorizonsS[] = {1, 2, 5, 10, 20, 30, 60};

}  // namespace

OutageAccumulator::OutageAccumulator(const FaultTimeline& faults, double reconverged_error_m)
    : threshold_m_(reconverged_error_m) {
  // a data gap is an outage for the estimator: no GNSS reaches it
  std::vector<Fault> outages = faults.OfKind(FaultKind::kGnssOutage);
  for (const Fault& f : faults.OfKind(FaultKind::kGnssDataGap)) outages.push_back(f);
  std::stable_sort(outages.begin(), outages.end(),
                   [](const Fault& a, const Fault& b) { return a.start < b.start; });
  for (std::size_t k = 0; k < outages.size(); ++k) {
    Window w;
    w.start = outages[k].start;
    w.end = outages[k].end;
    w.next_start = k + 1 < outages.size() ? outages[k + 1].start : Time::max();
    w.m.start_s = ToSeconds(w.start);
    w.m.end_s = ToSeconds(w.end);
    for (const double h : kHorizonsS) {
      if (h > w.m.end_s - w.m.start_s) break;
      w.latest.emplace_back();
    }
    windows_.push_back(std::move(w));
  }
}

void OutageAccumulator::Add(const ErrorSample& e) {
  const double h = e.horizontal();
  for (Window& w : windows_) {
    if (e.t >= w.start && e.t <= w.end) {
      ++w.m.samples;
      w.m.max_horizontal_error_m = std::max(w.m.max_horizontal_error_m, h);
      w.m.max_abs_error_enu_m = w.m.max_abs_error_enu_m.cwiseMax(e.err_enu_m.cwiseAbs());
    }
    for (std::size_t i = 0; i < w.latest.size(); ++i) {
      if (e.t >= w.start && e.t <= w.start + DurationFromSeconds(kHorizonsS[i])) w.latest[i] = h;
    }
    if (w.settled || e.t < w.end) continue;
    // reconvergence: the first solution after the end below the threshold that no solution at or
    // above it follows within 2 s (or before the next outage)
    if (w.candidate) {
      Time stay_until = *w.candidate + DurationFromSeconds(kStaySeconds);
      if (w.next_start < stay_until) stay_until = w.next_start;
      if (e.t > stay_until) {
        w.settled = true;
        w.m.reconvergence_time_s = ToSeconds(*w.candidate) - w.m.end_s;
        continue;
      }
      if (h >= threshold_m_) w.candidate.reset();
      continue;
    }
    if (h < threshold_m_) w.candidate = e.t;
  }
}

std::vector<OutageMetrics> OutageAccumulator::Result() const {
  std::vector<OutageMetrics> out;
  for (const Window& w : windows_) {
    OutageMetrics m = w.m;
    for (std::size_t i = 0; i < w.latest.size(); ++i) {
      if (w.latest[i]) m.growth.emplace_back(kHorizonsS[i], *w.latest[i]);
    }
    if (!w.settled && w.candidate)  // good to the end of the run
      m.reconvergence_time_s = ToSeconds(*w.candidate) - m.end_s;
    out.push_back(std::move(m));
  }
  return out;
}

std::vector<OutageMetrics> ComputeOutages(const std::vector<ErrorSample>& errors,
                                          const FaultTimeline& faults, double reconverged_error_m) {
  OutageAccumulator a(faults, reconverged_error_m);
  for (const ErrorSample& e : errors) a.Add(e);
  return a.Result();
}

namespace {

// Solutions missing from a gap of `gap_s` seconds: none up to 1.5 periods, else
// round(gap / period) − 1. A window edge counts like a solution, so a stream may start up to 1.5
// periods after the window opens (its phase) and end as much before it closes.
double MissingInGap(double gap_s, double period_s) {
  return gap_s > 1.5 * period_s ? std::round(gap_s / period_s) - 1 : 0.0;
}

}  // namespace

void OutputTimingAccumulator::Add(Time t_validity, WallTime wall_rx) {
  if (n_ > 0) dt_s_.Add(ToSeconds(t_validity - last_));
  if (n_ == 0) first_ = t_validity;
  last_ = t_validity;
  ++n_;
  if (wall_rx <= WallTime{}) return;  // no arrival time (virtual mode)
  if (!reordering_) {
    wall_.push_back(wall_rx);
    if (wall_.size() <= exact_limit_) return;
    // too many to hold: the sorted ones go out now, the rest through the reorder heap
    std::sort(wall_.begin(), wall_.end());
    for (const WallTime w : wall_) AddArrivalInterval(w);
    std::vector<WallTime>().swap(wall_);
    reordering_ = true;
    return;
  }
  heap_.push_back(wall_rx);
  std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
  if (heap_.size() <= kReorderArrivals) return;
  std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
  AddArrivalInterval(heap_.back());
  heap_.pop_back();
}

void OutputTimingAccumulator::AddArrivalInterval(WallTime wall) {
  if (last_wall_) iv_ms_.Add(static_cast<double>((wall - *last_wall_).count()) * 1e-6 * speed_);
  last_wall_ = wall;
}

namespace {

// |interval − median| percentiles of the arrival intervals (the jitter).
void SetJitter(const QuantileSketch& iv_ms, std::size_t exact_limit, OutputTiming& t) {
  const double med = iv_ms.Percentile(50);
  QuantileSketch dev(exact_limit);
  iv_ms.ForEach([&](double v, std::uint64_t n) {
    for (std::uint64_t i = 0; i < n; ++i) dev.Add(std::abs(v - med));
  });
  t.jitter_p50_ms = dev.Percentile(50);
  t.jitter_p99_ms = dev.Percentile(99);
  t.jitter_max_ms = dev.Percentile(100);
}

}  // namespace

OutputTiming OutputTimingAccumulator::Result(Time t_from, Time t_to) const {
  OutputTiming t;
  const double window_s = ToSeconds(t_to - t_from);
  if (window_s <= 0) return t;
  t.output_rate_hz = static_cast<double>(n_) / window_s;
  if (n_ == 0) {
    t.missing_fraction = 1.0;
    return t;
  }
  // the nominal period: the median interval (one solution alone says nothing about it)
  const double period_s = dt_s_.count() == 0 ? 0.0 : dt_s_.Percentile(50);
  if (period_s > 0) {
    double missing = MissingInGap(ToSeconds(first_ - t_from), period_s) +
                     MissingInGap(ToSeconds(t_to - last_), period_s);
    dt_s_.ForEach([&](double d, std::uint64_t n) {
      missing += static_cast<double>(n) * MissingInGap(d, period_s);
    });
    t.missing_fraction = missing / (static_cast<double>(n_) + missing);
  }
  if (!reordering_) {
    if (wall_.size() < 3) return t;
    std::vector<WallTime> wall = wall_;
    std::sort(wall.begin(), wall.end());
    QuantileSketch iv(exact_limit_);
    for (std::size_t i = 1; i < wall.size(); ++i)
      iv.Add(static_cast<double>((wall[i] - wall[i - 1]).count()) * 1e-6 * speed_);
    SetJitter(iv, exact_limit_, t);
    return t;
  }
  QuantileSketch iv = iv_ms_;
  std::vector<WallTime> rest = heap_;
  std::sort(rest.begin(), rest.end());
  std::optional<WallTime> last = last_wall_;
  for (const WallTime w : rest) {
    if (last) iv.Add(static_cast<double>((w - *last).count()) * 1e-6 * speed_);
    last = w;
  }
  SetJitter(iv, exact_limit_, t);
  return t;
}

OutputTiming ComputeOutputTiming(const std::vector<EstimateRecord>& records_in, Time t_from,
                                 Time t_to, double speed) {
  std::vector<EstimateRecord> records;
  for (const EstimateRecord& r : records_in) {
    if (r.t_validity >= t_from && r.t_validity <= t_to) records.push_back(r);
  }
  std::stable_sort(
      records.begin(), records.end(),
      [](const EstimateRecord& a, const EstimateRecord& b) { return a.t_validity < b.t_validity; });
  OutputTimingAccumulator a(speed);
  for (const EstimateRecord& r : records) a.Add(r.t_validity, r.wall_rx);
  return a.Result(t_from, t_to);
}

}  // namespace hil::harness

#include "hil/harness/core/quantile_sketch.h"

#include <algorithm>
#include <cmath>

#include "hil/harness/core/percentile.h"

namespace hil::harness {

QuantileSketch::QuantileSketch(std::size_t exact_limit)
    : exact_limit_(exact_limit),
      log_gamma_(std::log((1 + kRelativeAccuracy) / (1 - kRelativeAccuracy))) {}

void QuantileSketch::Add(double v) {
  if (std::isnan(v)) return;
  ++count_;
  min_ = std::min(min_, v);
  max_ = std::max(max_, v);
  if (sketching_) {
    AddToBuckets(v, 1);
    return;
  }
  if (values_.size() == exact_limit_) {  // one more than it holds
    StartSketching();
    AddToBuckets(v, 1);
    return;
  }
  values_.Add(v);
}

void QuantileSketch::Merge(const QuantileSketch& other) {
  if (!other.sketching_) {
    other.values_.ForEach([this](double v) { Add(v); });
    return;
  }
  if (!sketching_) StartSketching();
  count_ += other.count_;
  min_ = std::min(min_, other.min_);
  max_ = std::max(max_, other.max_);
  zeros_ += other.zeros_;
  for (const auto& [bucket, n] : other.positive_) positive_[bucket] += n;
  for (const auto& [bucket, n] : other.negative_) negative_[bucket] += n;
}

void QuantileSketch::StartSketching() {
  sketching_ = true;
  values_.ForEach([this](double v) { AddToBuckets(v, 1); });
  values_.Clear();
}

int QuantileSketch::BucketOf(double magnitude) const {
  // |v| ≤ 1e308 gives at most 354 000: far inside int
  constexpr double kLargest = 1e308;
  return static_cast<int>(std::ceil(std::log(std::min(magnitude, kLargest)) / log_gamma_));
}

double QuantileSketch::ValueOf(int bucket) const {
  // the midpoint of the bucket in relative terms: 2 γ^i / (γ + 1), within a of either end
  const double gamma = std::exp(log_gamma_);
  return 2.0 * std::exp(log_gamma_ * bucket) / (gamma + 1.0);
}

void QuantileSketch::AddToBuckets(double v, std::uint64_t n) {
  const double m = std::abs(v);
  if (m < kMinMagnitude) {
    zeros_ += n;
    return;
  }
  (v > 0 ? positive_ : negative_)[BucketOf(m)] += n;
}

std::vector<double> QuantileSketch::Sorted() const {
  std::vector<double> v;
  v.reserve(values_.size());
  values_.ForEach([&v](double x) { v.push_back(x); });
  std::sort(v.begin(), v.end());
  return v;
}

double QuantileSketch::RankValue(std::uint64_t k) const {
  if (k == 0) return min_;
  if (k + 1 >= count_) return max_;
  std::uint64_t seen = 0;
  const auto clamp = [this](double v) { return std::clamp(v, min_, max_); };
  for (auto it = negative_.rbegin(); it != negative_.rend(); ++it) {
    seen += it->second;
    if (k < seen) return clamp(-ValueOf(it->first));
  }
  seen += zeros_;
  if (k < seen) return clamp(0.0);
  for (const auto& [bucket, n] : positive_) {
    seen += n;
    if (k < seen) return clamp(ValueOf(bucket));
  }
  return max_;
}

double QuantileSketch::Percentile(double pct) const {
  if (count_ == 0) return 0;
  if (!sketching_) return PercentileOfSorted(Sorted(), pct);
  // the same interpolation between ranks as PercentileOfSorted
  const double pos = pct / 100.0 * static_cast<double>(count_ - 1);
  const auto lo = static_cast<std::uint64_t>(std::floor(pos));
  const std::uint64_t hi = std::min(lo + 1, count_ - 1);
  const double f = pos - static_cast<double>(lo);
  return RankValue(lo) * (1 - f) + RankValue(hi) * f;
}

void QuantileSketch::ForEach(const std::function<void(double, std::uint64_t)>& f) const {
  if (!sketching_) {
    const std::vector<double> sorted = Sorted();
    for (std::size_t i = 0; i < sorted.size();) {
      std::size_t j = i + 1;
      while (j < sorted.size() && sorted[j] == sorted[i]) ++j;
      f(sorted[i], j - i);
      i = j;
    }
    return;
  }
  const auto clamp = [this](double v) { return std::clamp(v, min_, max_); };
  for (auto it = negative_.rbegin(); it != negative_.rend(); ++it)
    f(clamp(-ValueOf(it->first)), it->second);
  if (zeros_ > 0) f(clamp(0.0), zeros_);
  for (const auto& [bucket, n] : positive_) f(clamp(ValueOf(bucket)), n);
}

std::vector<std::pair<double, double>> CdfPoints(const QuantileSketch& sketch,
                                                 std::size_t max_points) {
  std::vector<std::pair<double, double>> out;
  const std::uint64_t n = sketch.count();
  if (n == 0 || max_points < 2) return out;
  // a point each time the running count reaches the next of max_points − 1 evenly spaced ranks
  const double step = static_cast<double>(n) / static_cast<double>(max_points - 1);
  double next = 0;
  std::uint64_t seen = 0;
  sketch.ForEach([&](double v, std::uint64_t k) {
    seen += k;
    if (static_cast<double>(seen) < next && seen < n) return;
    out.emplace_back(v, 100.0 * static_cast<double>(seen) / static_cast<double>(n));
    while (next <= static_cast<double>(seen)) next += step;
  });
  return out;
}

}  // namespace hil::harness

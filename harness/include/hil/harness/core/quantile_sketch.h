#pragma once
/// @file
/// Percentiles of a stream of values in bounded memory (the estimate errors of a run, the links'
/// per-byte schedule errors of a real-time run). Up to `exact_limit` values are held as they are
/// and a percentile is exact: the same linear interpolation of the sorted values as Percentile()
/// (evaluator.h), bit for bit. Past that many values the sketch holds counts in logarithmic buckets
/// instead (the DDSketch of Masson, Rim and Lee, VLDB 2019): every value v with |v| ≥ kMinMagnitude
/// falls into the bucket ((1+a)/(1−a))^(i−1) < |v| ≤ ((1+a)/(1−a))^i and is represented by a value
/// within a relative a = kRelativeAccuracy of it, so a percentile is within a relative a of the
/// exact one (values below kMinMagnitude in magnitude count as 0; the smallest and largest values
/// are kept exactly, so the 0th and 100th percentiles stay exact). The number of buckets grows with
/// the logarithm of the values' range, not with their number: a range of 1e-6 to 1e6 takes at most
/// 13 816 buckets. The exact values wait on disk but for the last few thousand (spill_file.h:
/// issue 40, six sets of 2^18 values were 12 MiB of a long run's memory); a percentile or ForEach
/// reads them back and sorts them for the moment of the call.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <vector>

#include "hil/harness/core/spill_file.h"

namespace hil::harness {

class QuantileSketch {
 public:
  /// Our choice: 2^18 values (2 MiB of disk) held exactly: 7.3 h of 10 Hz solutions, 44 min at
  /// 100 Hz (every scenario of vectors/ is exact; a run holds six such sets at most).
  static constexpr std::size_t kExactLimit = std::size_t{1} << 18;
  /// Our choice: 0.1 % relative error of a percentile once the values are no longer held.
  static constexpr double kRelativeAccuracy = 1e-3;
  static constexpr double kMinMagnitude = 1e-12;

  QuantileSketch() : QuantileSketch(kExactLimit) {}
  explicit QuantileSketch(std::size_t exact_limit);

  /// Adds a value (NaN is left out).
  void Add(double v);
  /// Adds every value of `other` (of the same relative accuracy): the percentiles are those of
  /// both sets' values, exact while the two together hold no more than this one's limit.
  void Merge(const QuantileSketch& other);
  std::uint64_t count() const { return count_; }
  /// True while every value is held (the percentiles are exact).
  bool exact() const { return !sketching_; }
  /// The percentile `pct` (0–100) by linear interpolation between ranks; 0 when empty.
  double Percentile(double pct) const;
  double min() const { return min_; }
  double max() const { return max_; }
  /// Each distinct value (exact) or bucket's representative value (sketch) with its count, in
  /// ascending order.
  void ForEach(const std::function<void(double value, std::uint64_t count)>& f) const;
  /// Values or buckets held in memory: what bounds the memory.
  std::size_t retained() const { return values_.in_memory() + positive_.size() + negative_.size(); }

 private:
  void StartSketching();
  void AddToBuckets(double v, std::uint64_t n);
  int BucketOf(double magnitude) const;
  double ValueOf(int bucket) const;
  /// The value of rank `k` (0-based) in sketch mode.
  double RankValue(std::uint64_t k) const;
  /// The exact values, sorted (read from the file for the caller).
  std::vector<double> Sorted() const;

  std::size_t exact_limit_;
  bool sketching_ = false;
  std::uint64_t count_ = 0;
  double min_ = std::numeric_limits<double>::infinity();
  double max_ = -std::numeric_limits<double>::infinity();
  SpillFile<double> values_;  // exact mode, in the order they came
  double log_gamma_;
  std::map<int, std::uint64_t> positive_, negative_;  // bucket → count (negative: of |v|)
  std::uint64_t zeros_ = 0;
};

/// The empirical CDF of a sketch as at most `max_points` points (value, % of values at or below),
/// for a plot: every value while there are no more than that, else points at evenly spaced ranks
/// with the smallest and the largest value always among them.
std::vector<std::pair<double, double>> CdfPoints(const QuantileSketch& sketch,
                                                 std::size_t max_points);

}  // namespace hil::harness

#pragma once
/// @file
/// A time series for a plot in bounded memory: the series' time is cut into at most `buckets`
/// buckets of equal width, and each bucket keeps its first item and the items of the smallest and
/// largest key (a spike survives, whatever the run's length). The width starts at `width_s` and
/// doubles (neighbouring buckets merged) whenever the series outgrows the buckets, so a short run
/// keeps every item and a long one at most 3 × `buckets`.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace hil::harness {

template <class T>
class SeriesDecimator {
 public:
  SeriesDecimator(std::size_t buckets, double width_s) : capacity_(buckets), width_s_(width_s) {}

  /// Adds an item at time `t_s` (not decreasing from one call to the next) with its `key`.
  void Add(double t_s, double key, const T& item) {
    if (!started_) started_ = true, t0_s_ = t_s;
    auto index = static_cast<std::size_t>(std::max(0.0, std::floor((t_s - t0_s_) / width_s_)));
    while (index >= capacity_) {
      Merge();
      index /= 2;
    }
    if (buckets_.size() <= index) buckets_.resize(index + 1);
    const Entry e{seq_++, key, item};
    Bucket& b = buckets_[index];
    if (!b.used) {
      b = Bucket{true, e, e, e};
      return;
    }
    if (key < b.min.key) b.min = e;
    if (key > b.max.key) b.max = e;
  }

  /// The items kept, in the order they were added.
  std::vector<T> Points() const {
    std::vector<T> out;
    for (const Bucket& b : buckets_) {
      if (!b.used) continue;
      const Entry* e[3] = {&b.first, &b.min, &b.max};
      std::sort(e, e + 3, [](const Entry* x, const Entry* y) { return x->seq < y->seq; });
      for (int i = 0; i < 3; ++i) {
        if (i == 0 || e[i]->seq != e[i - 1]->seq) out.push_back(e[i]->item);
      }
    }
    return out;
  }
  /// Items held (3 per bucket): what bounds the memory.
  std::size_t retained() const { return 3 * buckets_.size(); }

 private:
  struct Entry {
    std::uint64_t seq = 0;
    double key = 0;
    T item{};
  };
  struct Bucket {
    bool used = false;
    Entry first, min, max;
  };
  // neighbouring buckets become one of twice the width
  void Merge() {
    std::vector<Bucket> merged((buckets_.size() + 1) / 2);
    for (std::size_t i = 0; i < buckets_.size(); ++i) {
      const Bucket& b = buckets_[i];
      if (!b.used) continue;
      Bucket& m = merged[i / 2];
      if (!m.used) {
        m = b;
        continue;
      }
      if (b.min.key < m.min.key) m.min = b.min;
      if (b.max.key > m.max.key) m.max = b.max;
    }
    buckets_ = std::move(merged);
    width_s_ *= 2;
  }

  std::size_t capacity_;
  double width_s_;
  bool started_ = false;
  double t0_s_ = 0;
  std::uint64_t seq_ = 0;
  std::vector<Bucket> buckets_;
};

}  // namespace hil::harness

#include "hil/estimator/navd/input_merge.h"

#include <algorithm>
#include <tuple>
#include <utility>

namespace hil::estimator {
namespace {

bool Before(const MergeItem& a, const MergeItem& b) {
  return std::tuple(a.t, a.kind, a.link, a.seq) < std::tuple(b.t, b.kind, b.link, b.seq);
}

}  // namespace

InputMerge::InputMerge(Nanoseconds window, std::size_t capacity, Release release)
    : window_(window), capacity_(std::max<std::size_t>(capacity, 1)), release_(std::move(release)) {
  if (enabled()) items_.reserve(capacity_ * 2);
}

void InputMerge::Add(MergeItem item) {
  item.seq = next_seq_++;
  if (!enabled()) {
    Pass(item);
    return;
  }
  GpsTime watermark{};
  if (item.kind == MergeItem::Kind::kImu) {
    if (!newest_imu_ || item.t > *newest_imu_) newest_imu_ = item.t;
  } else if (!newest_gnss_ || item.t > *newest_gnss_) {
    newest_gnss_ = item.t;
  }
  if (head_ > 0 && items_.size() == items_.capacity()) {  // compact: no reallocation
    items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
    head_ = 0;
  }
  const auto at = std::upper_bound(items_.begin() + static_cast<std::ptrdiff_t>(head_),
                                   items_.end(), item, Before);
  items_.insert(at, std::move(item));
  if (newest_imu_) {
    watermark = *newest_imu_ - window_;
  } else {
    watermark = *newest_gnss_ - 2 * window_;
  }
  if (newest_imu_ && newest_gnss_) watermark = std::max(watermark, *newest_gnss_ - 2 * window_);
  ReleaseUpTo(watermark);
  while (held() > capacity_) ReleaseFront();
}

void InputMerge::ReleaseUpTo(GpsTime watermark) {
  while (held() > 0) {
    const MergeItem& front = items_[head_];
    // an item older than what already went on is late: it goes at once
    if (front.t > watermark && !(released_to_ && front.t <= *released_to_)) break;
    ReleaseFront();
  }
}

void InputMerge::ReleaseFront() {
  ++head_;
  Pass(items_[head_ - 1]);
}

void InputMerge::Pass(const MergeItem& m) {
  if (m.kind == MergeItem::Kind::kGnss) {
    counters_.nmea = m.nmea;
    counters_.ubx = m.ubx;
  } else if (m.from_mcu) {
    counters_.mcu = m.mcu;
    counters_.mcu_adapter = m.mcu_adapter;
  } else {
    counters_.j1939 = m.j1939;
  }
  if (!released_to_ || m.t > *released_to_) released_to_ = m.t;
  release_(m);
}

void InputMerge::ReleaseAll() {
  while (held() > 0) ReleaseFront();
  items_.clear();
  head_ = 0;
}

}  // namespace hil::estimator

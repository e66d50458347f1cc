#include "hil/harness/replay/replay_device.h"

#include <algorithm>
#include <utility>

namespace hil::harness {

ReplayDevice::ReplayDevice(std::vector<ReplayItem> items, std::vector<int> bauds)
    : items_(std::move(items)), bauds_(std::move(bauds)) {
  std::stable_sort(items_.begin(), items_.end(),
                   [](const ReplayItem& a, const ReplayItem& b) { return a.t < b.t; });
}

Time ReplayDevice::next_event_time() const {
  return next_ < items_.size() ? items_[next_].t : Time::max();
}

void ReplayDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  for (; next_ < items_.size() && items_[next_].t == truth.t; ++next_) {
    const ReplayItem& item = items_[next_];
    if (item.port < 0) {
      out.can.push_back(link::ToDeviceFrame(item.record.frame, item.t));
      continue;
    }
    SerialMessage m;
    m.t_ready = item.t;
    m.port = item.port;
    m.bytes = item.record.bytes;
    m.name = item.record.name;
    m.byte_period = Duration{item.record.byte_period_ns};
    out.serial.push_back(std::move(m));
  }
}

}  // namespace hil::harness

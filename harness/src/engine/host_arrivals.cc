#include "hil/harness/engine/host_arrivals.h"

#include <algorithm>
#include <mutex>
#include <utility>

namespace hil::harness {

Time HostArrivals::Next() const {
  Time t = Time::max();
  if (!bytes_.empty()) t = std::min(t, bytes_.front().t);
  if (!frames_.empty()) t = std::min(t, frames_.front().t);
  return t;
}

void HostArrivals::ReadHosts(Time t_rx, DeviceIo& io,
                             const std::function<void(const SerialEndpoint&)>& on_read) {
  io.PollHostFds();  // one poll() instead of a read() per port (it hands over bytes in flight too)
  const EngineDevices& set = io.devices();
  std::size_t k = 0;
  for (std::size_t d = 0; d < set.devices.size(); ++d) {
    for (std::size_t p = 0; p < set.endpoints[d].size(); ++p) {
      const pollfd& pf = io.host_fds()[k++];
      if (pf.fd >= 0 && pf.revents == 0) continue;  // nothing from the host on this port
      std::string rx = set.endpoints[d][p]->PollHost(t_rx, true);
      if (rx.empty()) continue;
      if (on_read) on_read(*set.endpoints[d][p]);
      bytes_.push_back({t_rx, d, p, std::move(rx)});
    }
  }
}

std::size_t HostArrivals::ReadBus(Time t_rx, DeviceIo& io) {
  io.PollBus();
  // the programs' frames arrive now: the capture says so (read between turns, they would be
  // stamped whenever the run happened to look)
  if (CanEndpoint* can = io.devices().can) {
    const std::unique_lock<std::mutex> lock = io.pacer().LinksLock();
    for (const CanFrame& f : can->TakeArrivals(t_rx)) io.bus_frames().push_back(f);
  }
  std::size_t n = 0;
  for (const CanFrame& f : io.TakeUnrouted()) {
    frames_.push_back({t_rx, f});
    ++n;
  }
  return n;
}

std::optional<HostArrivals::Delivered> HostArrivals::DeliverBytes(Time limit, DeviceIo& io,
                                                                  DeviceOutput& out) {
  if (bytes_.empty() || bytes_.front().t > limit) return std::nullopt;
  const HostBytes h = std::move(bytes_.front());
  bytes_.pop_front();
  const EngineDevices& set = io.devices();
  const int port = static_cast<int>(h.port);
  set.devices[h.device]->OnHostBytes(port, h.t, h.bytes, out);
  set.endpoints[h.device][h.port]->set_baud(set.devices[h.device]->baud(port));
  const Delivered delivered{h.device, h.t, !out.serial.empty()};
  io.Dispatch(h.device, out);
  return delivered;
}

bool HostArrivals::DeliverFrame(Time limit, DeviceIo& io, DeviceOutput& out) {
  if (frames_.empty() || frames_.front().t > limit) return false;
  io.DeliverBusFrame(frames_.front().t, frames_.front().frame, out);
  frames_.pop_front();
  return true;
}

}  // namespace hil::harness

#include "hil/harness/engine/clocked_host_turns.h"

#include <algorithm>
#include <utility>

#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness {

ClockedHostTurns::ClockedHostTurns(lockstep::LockstepHost& host, ClockedPacer& pacer,
                                   lockstep::LockstepHost::WaitStep on_wait)
    : host_(host), pacer_(pacer), on_wait_(std::move(on_wait)) {}

std::optional<Time> ClockedHostTurns::NextTurn() const {
  std::optional<Time> t = pacer_.NextChunkEnd();
  if (const std::optional<Time> d = host_.EarliestDeadline(); d && (!t || *d < *t)) t = d;
  // never behind the programs' clock (a deadline met at the last turn is in the past)
  if (t && *t < host_.now()) t = host_.now();
  return t;
}

Time ClockedHostTurns::NextAction() const {
  Time t = NextTurn().value_or(Time::max());
  if (!arrivals_.empty()) t = std::min(t, arrivals_.front().t);
  if (!bus_arrivals_.empty()) t = std::min(t, bus_arrivals_.front().t);
  return t;
}

bool ClockedHostTurns::BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                                   DeviceOutput& out) {
  const Time limit = std::min(t_event, t_end);
  if (!started_) {
    started_ = true;  // the programs' start-up, at t = 0
    if (!Turn(Time{}, io, true)) io.Refuse();
    return true;
  }
  if (!arrivals_.empty() && arrivals_.front().t <= limit) {
    DeliverHostBytes(arrivals_.front(), io, out);
    arrivals_.pop_front();
    return true;
  }
  if (!bus_arrivals_.empty() && bus_arrivals_.front().t <= limit) {
    io.DeliverBusFrame(bus_arrivals_.front().t, bus_arrivals_.front().frame, out);
    bus_arrivals_.pop_front();
    return true;
  }
  const std::optional<Time> t = NextTurn();
  if (!t || *t > limit) return false;
  if (Turn(*t, io)) {
    monitor.OnHostTurn(*t);
  } else {
    io.Refuse();
  }
  return true;
}

bool ClockedHostTurns::Turn(Time t, DeviceIo& io, bool wake) {
  host_.SetNow(t);
  touched_ |= pacer_.WriteDue(t);
  if (pacer_.TakeBusWritten()) touched_ |= lockstep::kOtherFd;
  // every thread sleeps past t or waits on links untouched: the bytes wait for them in the pty,
  // nothing runs, nothing to read
  if (!wake && !host_.NeedsWake(t, touched_)) return true;
  if (wake) {
    host_.Wake();
  } else {
    host_.Wake(t, touched_ | lockstep::kEveryGrant);
  }
  touched_ = 0;
  if (!host_.WaitIdle(on_wait_)) return false;
  ReadHosts(t, io);
  if (io.devices().steering) ReadBus(t, io);
  return true;
}

bool ClockedHostTurns::Drain(DeviceIo& io) {
  // what Flush wrote ended by the last chunk's end at the latest: the programs' clock gets there
  Time t = std::max(host_.now(), io.t_last_event());
  for (const auto& ports : io.devices().endpoints) {
    for (const auto& ep : ports) t = std::max(t, ep->last_queued_end());
  }
  return Turn(t, io, true);
}

void ClockedHostTurns::ReadHosts(Time t, DeviceIo& io) {
  io.PollHostFds();
  const EngineDevices& set = io.devices();
  std::size_t k = 0;
  for (std::size_t d = 0; d < set.devices.size(); ++d) {
    for (std::size_t p = 0; p < set.endpoints[d].size(); ++p) {
      const pollfd& pf = io.host_fds()[k++];
      if (pf.fd >= 0 && pf.revents == 0) continue;
      std::string rx = set.endpoints[d][p]->PollHost(t, true);
      if (rx.empty()) continue;
      // room on that link again: a thread waiting to write there looks at the next grant
      touched_ |= LinkBitOf(set.endpoints[d][p].get());
      arrivals_.push_back({t, d, p, std::move(rx)});
    }
  }
}

std::uint64_t ClockedHostTurns::LinkBitOf(const SerialEndpoint* ep) const {
  const std::vector<SerialEndpoint*>& links = pacer_.endpoints();
  const auto it = std::find(links.begin(), links.end(), ep);
  return it == links.end() ? lockstep::kOtherFd
                           : ClockedPacer::LinkBit(static_cast<std::size_t>(it - links.begin()));
}

void ClockedHostTurns::ReadBus(Time t, DeviceIo& io) {
  io.PollBus();
  if (CanEndpoint* can = io.devices().can) {
    for (const CanFrame& f : can->TakeArrivals(t)) io.bus_frames().push_back(f);
  }
  for (const CanFrame& f : io.TakeUnrouted()) {
    bus_arrivals_.push_back({t, f});
    touched_ |= lockstep::kOtherFd;  // frames read off the bus: room for the sender's next
  }
}

void ClockedHostTurns::DeliverHostBytes(const HostBytes& h, DeviceIo& io, DeviceOutput& out) {
  const EngineDevices& set = io.devices();
  const int port = static_cast<int>(h.port);
  set.devices[h.device]->OnHostBytes(port, h.t, h.bytes, out);
  set.endpoints[h.device][h.port]->set_baud(set.devices[h.device]->baud(port));
  io.Dispatch(h.device, out);
}

}  // namespace hil::harness

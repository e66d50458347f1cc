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
  return std::min(t, arrivals_.Next());
}

bool ClockedHostTurns::BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                                   DeviceOutput& out) {
  const Time limit = std::min(t_event, t_end);
  if (!started_) {
    started_ = true;  // the programs' start-up, at t = 0
    if (!Turn(Time{}, io, true)) io.Refuse();
    return true;
  }
  if (arrivals_.DeliverBytes(limit, io, out) || arrivals_.DeliverFrame(limit, io, out)) return true;
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
  // room on a link read again: a thread waiting to write there looks at the next grant. Only
  // when the programs may have written: most turns hand a message over and get none back.
  if (wake || host_.TakeHostWrites())
    arrivals_.ReadHosts(t, io, [this](const SerialEndpoint& ep) { touched_ |= LinkBitOf(&ep); });
  // frames read off the bus: room for the sender's next
  if (io.devices().steering && arrivals_.ReadBus(t, io) > 0) touched_ |= lockstep::kOtherFd;
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

std::uint64_t ClockedHostTurns::LinkBitOf(const SerialEndpoint* ep) const {
  const std::vector<SerialEndpoint*>& links = pacer_.endpoints();
  const auto it = std::find(links.begin(), links.end(), ep);
  return it == links.end() ? lockstep::kOtherFd
                           : ClockedPacer::LinkBit(static_cast<std::size_t>(it - links.begin()));
}

}  // namespace hil::harness

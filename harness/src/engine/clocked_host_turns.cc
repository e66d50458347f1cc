#include "hil/harness/engine/clocked_host_turns.h"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "hil/harness/engine/host_link_access.h"
#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness {

ClockedHostTurns::ClockedHostTurns(lockstep::LockstepHost& host, ClockedPacer& pacer,
                                   lockstep::LockstepHost::WaitStep on_wait, bool lookahead_allowed)
    : host_(host),
      pacer_(pacer),
      on_wait_(std::move(on_wait)),
      lookahead_allowed_(lookahead_allowed) {}

std::optional<Time> ClockedHostTurns::NextTurn() const {
  std::optional<Time> t = pacer_.NextChunkEnd();
  if (const std::optional<Time> d = host_.EarliestDeadline(); d && (!t || *d < *t)) t = d;
  // never behind the programs' clock (a deadline met at the last turn is in the past)
  if (t && *t < host_.now()) t = host_.now();
  return t;
}

Time ClockedHostTurns::NextAction() const {
  if (lookahead_) return Time::max();
  Time t = NextTurn().value_or(Time::max());
  return std::min(t, arrivals_.Next());
}

bool ClockedHostTurns::BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                                   DeviceOutput& out) {
  const Time limit = std::min(t_event, t_end);
  if (!started_) {
    started_ = true;  // the programs' start-up, at t = 0
    if (Turn(Time{}, io, true)) {
      MaybeLookAhead();
    } else {
      io.Refuse();
    }
    return true;
  }
  if (lookahead_) {
    if (host_.EpollSeen() && !std::exchange(epoll_noted_, true))
      std::fprintf(stderr,
                   "hil: --lockstep: a program waited in epoll while hil wrote ahead: what it "
                   "saw ready there may have depended on the machine (use --no-lookahead)\n");
    if (lookahead_->Step(limit)) return false;
    io.Refuse();
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
  if (lookahead_) {
    if (!lookahead_->Finish(t)) return false;
  } else {
    // the chunks left and the programs' deadlines before t: a turn each, as during the run (the
    // programs read the last bytes at their arrival, as with lookahead)
    for (std::optional<Time> next = NextTurn(); next && *next < t; next = NextTurn()) {
      if (!Turn(*next, io)) return false;
    }
  }
  return Turn(t, io, true);
}

void ClockedHostTurns::MaybeLookAhead() {
  const std::vector<SerialEndpoint*>& links = pacer_.endpoints();
  if (!lookahead_allowed_ || links.empty() ||
      links.size() > static_cast<std::size_t>(lockstep::kFeedLinks) || host_.EpollSeen())
    return;
  std::vector<int> pids;
  for (const auto& p : host_.Processes()) pids.push_back(p.pid);
  if (!LinksHeldReadOnly(pids, links)) return;
  host_.SetLookahead(true);
  lookahead_.emplace(host_, links, on_wait_);
}

std::uint64_t ClockedHostTurns::LinkBitOf(const SerialEndpoint* ep) const {
  const std::vector<SerialEndpoint*>& links = pacer_.endpoints();
  const auto it = std::find(links.begin(), links.end(), ep);
  return it == links.end() ? lockstep::kOtherFd
                           : ClockedPacer::LinkBit(static_cast<std::size_t>(it - links.begin()));
}

}  // namespace hil::harness

// LockstepHost's side of the lookahead (lockstep_advance.h): the feeds hil publishes the chunks
// it writes ahead in, the horizon, and the wait until the programs have caught up with it.
#include "hil/harness/lockstep/lockstep_advance.h"
#include "hil/harness/lockstep/lockstep_host.h"
#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness::lockstep {

void LockstepHost::SetLookahead(bool on) {
  if (on) {
    // the programs are idle (after a turn), and nothing is published: they wait for hil
    shared_->horizon_ns.store(shared_->now_ns.load());
    shared_->stalled.store(1);
  }
  shared_->lookahead.store(on ? 1 : 0);
}

bool LockstepHost::EpollSeen() const { return shared_->epoll_seen.load() != 0; }

std::uint64_t LockstepHost::FeedConsumed(int k) const { return shared_->feeds[k].consumed.load(); }

std::size_t LockstepHost::FeedFree(int k) const {
  const LinkFeed& f = shared_->feeds[k];
  const std::uint64_t waiting = f.published.load() - f.arrived_entries.load();
  return static_cast<std::size_t>(kFeedEntries) - static_cast<std::size_t>(waiting);
}

void LockstepHost::Publish(int k, std::uint64_t end_byte, Time arrival) {
  LinkFeed& f = shared_->feeds[k];
  const std::uint64_t i = f.published.load();
  f.ring[i % kFeedEntries].end_byte.store(end_byte);
  f.ring[i % kFeedEntries].arrival_ns.store((arrival - Time{}).count());
  f.published.store(i + 1);
}

void LockstepHost::SetHorizon(Time t) {
  const std::int64_t ns = (t - Time{}).count();
  if (ns > shared_->horizon_ns.load()) shared_->horizon_ns.store(ns);
}

bool LockstepHost::Stalled() const { return shared_->stalled.load() != 0; }

void LockstepHost::MoveClock() { lockstep::MoveClock(*shared_); }

bool LockstepHost::WaitStalled(const WaitStep& on_wait) {
  return WaitUntil(
      on_wait, [this] { return Stalled() && AllSlotsIdle(*shared_); }, true);
}

}  // namespace hil::harness::lockstep

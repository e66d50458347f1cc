#pragma once
/// @file
/// Lookahead (issue 42): moving the programs' clock without a turn of hil's per message. Header
/// only, no allocation, no lock but the shared spin lock: hil and the preload library both
/// include it.
///
/// When hil writes ahead (`Shared::lookahead`), every chunk it writes to a link with a feed is in
/// that feed with its arrival time before (or as) the bytes reach the pty, and `horizon_ns` says up
/// to which emulated time every arrival is known. The party that finds the programs idle (the
/// thread whose acknowledgement made them idle, or hil after it wrote more) moves the clock as a
/// host turn of hil's would (clocked_host_turns.h): to the earliest of the next arrival and the
/// waiting threads' deadlines, marks the chunks that arrived by then, and wakes the threads that
/// concerns (a deadline come, a link of theirs with bytes arrived, kEveryGrant); a move that
/// concerns nobody is followed by the next. Beyond the horizon it stops and says so (`stalled`).
/// The moves depend only on the feeds and the threads' waits, so they are the per-message turns'
/// in every run, whoever makes them.

#include <sched.h>
#include <unistd.h>

#include <climits>
#include <cstdint>

#include <linux/futex.h>
#include <sys/syscall.h>

#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness::lockstep {

/// A slot counts as idle: free, or waiting having looked since it was last asked to.
inline bool SlotIsIdle(const ThreadSlot& s) {
  return s.tid.load() == 0 || (s.state.load() == kWaiting && s.acked.load() == s.seq.load());
}

inline bool AllSlotsIdle(const Shared& sh) {
  const int used = sh.slots_used.load() < kMaxThreads ? sh.slots_used.load() : kMaxThreads;
  for (int i = 0; i < used; ++i) {
    if (!SlotIsIdle(sh.slots[i])) return false;
  }
  return true;
}

/// Asks slot `s`'s thread to look again (`self`: the caller's own slot, which needs no wake-up).
inline void GrantSlot(ThreadSlot& s, const ThreadSlot* self = nullptr) {
  s.seq.fetch_add(1);
  if (&s == self) return;
  syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&s.seq), FUTEX_WAKE, INT_MAX, nullptr,
          nullptr, 0);
}

/// Whether a move to emulated `t_ns` that brought bytes on the links `touched` concerns slot `s`
/// (as LockstepHost::Concerns).
inline bool MoveConcerns(const ThreadSlot& s, std::int64_t t_ns, std::uint64_t touched) {
  if (s.tid.load() == 0) return false;
  if (!SlotIsIdle(s) || s.deadline_ns.load() <= t_ns) return true;
  return s.on_descriptors.load() != 0 && (s.links.load() & touched) != 0;
}

/// Bytes of feed `k` that have arrived and the programs have not read.
inline std::uint64_t FeedAvailable(const Shared& sh, int k) {
  const LinkFeed& f = sh.feeds[k];
  const std::uint64_t arrived = f.arrived_bytes.load();
  const std::uint64_t consumed = f.consumed.load();
  return arrived > consumed ? arrived - consumed : 0;
}

enum class MoveResult { kBusy, kGranted, kStalled };

/// The next emulated time the clock moves to (kNoDeadline: none): the earliest chunk not yet
/// arrived and the earliest deadline of a waiting thread, never before `now_ns`.
inline std::int64_t NextMoveNs(const Shared& sh) {
  std::int64_t t = kNoDeadline;
  for (int k = 0; k < kFeedLinks; ++k) {
    const LinkFeed& f = sh.feeds[k];
    const std::uint64_t next = f.arrived_entries.load();
    if (next >= f.published.load()) continue;
    const std::int64_t a = f.ring[next % kFeedEntries].arrival_ns.load();
    if (a < t) t = a;
  }
  const int used = sh.slots_used.load() < kMaxThreads ? sh.slots_used.load() : kMaxThreads;
  for (int i = 0; i < used; ++i) {
    const ThreadSlot& s = sh.slots[i];
    if (s.tid.load() == 0 || s.state.load() != kWaiting) continue;
    if (s.deadline_ns.load() < t) t = s.deadline_ns.load();
  }
  const std::int64_t now = sh.now_ns.load();
  return t != kNoDeadline && t < now ? now : t;
}

/// Marks the chunks that have arrived by `t_ns`; returns the links that got bytes (their bits).
inline std::uint64_t MarkArrivals(Shared& sh, std::int64_t t_ns) {
  std::uint64_t touched = 0;
  for (int k = 0; k < kFeedLinks; ++k) {
    LinkFeed& f = sh.feeds[k];
    std::uint64_t next = f.arrived_entries.load();
    const std::uint64_t published = f.published.load();
    const std::uint64_t first = next;
    while (next < published && f.ring[next % kFeedEntries].arrival_ns.load() <= t_ns) {
      f.arrived_bytes.store(f.ring[next % kFeedEntries].end_byte.load());
      ++next;
    }
    if (next == first) continue;
    f.arrived_entries.store(next);
    touched |= std::uint64_t{1} << k;
  }
  return touched;
}

/// Moves the clock while the programs are idle until a move wakes a thread (kGranted), the next
/// move lies beyond the horizon or there is none (kStalled: `stalled` set), or a thread runs
/// (kBusy). The caller holds `advancing`; `self`: its slot, if it is a thread of the programs.
inline MoveResult MoveClockLocked(Shared& sh, const ThreadSlot* self) {
  for (;;) {
    if (!AllSlotsIdle(sh)) return MoveResult::kBusy;
    const std::int64_t t = NextMoveNs(sh);
    if (t == kNoDeadline || t > sh.horizon_ns.load()) {
      sh.stalled.store(1);
      return MoveResult::kStalled;
    }
    sh.now_ns.store(t);
    const std::uint64_t touched = MarkArrivals(sh, t) | kEveryGrant;
    bool granted = false;
    const int used = sh.slots_used.load() < kMaxThreads ? sh.slots_used.load() : kMaxThreads;
    for (int i = 0; i < used; ++i) {
      if (!MoveConcerns(sh.slots[i], t, touched)) continue;
      GrantSlot(sh.slots[i], self);
      granted = true;
    }
    if (granted) {
      sh.advances.fetch_add(1);
      return MoveResult::kGranted;
    }
  }
}

/// Takes the spin lock and moves the clock (MoveClockLocked). While another party holds the lock,
/// this waits for it as long as the programs stay idle (the holder may have looked before this
/// thread's acknowledgement); kBusy when they no longer are.
inline MoveResult MoveClock(Shared& sh, const ThreadSlot* self = nullptr) {
  for (;;) {
    std::uint32_t free = 0;
    if (sh.advancing.compare_exchange_strong(free, 1)) break;
    if (!AllSlotsIdle(sh)) return MoveResult::kBusy;
    sched_yield();  // the holder may be a thread this one's CPU preempted
  }
  sh.stalled.store(0);
  const MoveResult r = MoveClockLocked(sh, self);
  sh.advancing.store(0);
  return r;
}

}  // namespace hil::harness::lockstep

#pragma once
/// @file
/// hil's side of the shared clock (lockstep_shared.h): creates the shared file the programs under
/// test map through libhil_lockstep.so, publishes emulated time, wakes them (a grant) and waits
/// until every thread of theirs waits again (idle), without looking at /proc. A thread that died
/// without leaving its slot (its process was killed) is noticed when a wait has lasted
/// kLivenessCheck and no longer waited for.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/wall_time.h"

namespace hil::harness::lockstep {

struct Shared;

class LockstepHost {
 public:
  /// A process that loaded the library.
  struct Process {
    int pid = 0;
    std::string name;
  };
  /// Counts for the report.
  struct Stats {
    std::uint64_t grants = 0;              ///< times hil woke the programs
    std::uint64_t slept = 0;               ///< waits for idle that slept on the futex
    Duration wait{};                       ///< wall time spent waiting for idle
    std::uint64_t thread_waits = 0;        ///< waits the programs' threads blocked in (all slots)
    std::uint64_t thread_looks = 0;        ///< times they looked at an unmet condition (all slots)
    std::uint64_t descriptor_lookups = 0;  ///< fstats the library made to tell descriptors apart
  };
  /// Called while a wait for idle lasts (every kStep): the threads not idle, whether this is a
  /// new wait. False gives the wait up.
  using WaitStep = std::function<bool(std::size_t busy_threads, bool new_wait)>;
  static constexpr Duration kStep = std::chrono::milliseconds(1);
  static constexpr Duration kLivenessCheck = std::chrono::milliseconds(1);

  /// Creates `path` (removed again by the destructor); emulated t = 0 is UTC `utc_epoch_ns`.
  /// @throws std::runtime_error when the file cannot be made.
  LockstepHost(std::string path, std::int64_t utc_epoch_ns);
  ~LockstepHost();
  LockstepHost(const LockstepHost&) = delete;
  LockstepHost& operator=(const LockstepHost&) = delete;

  const std::string& path() const { return path_; }
  /// Emulated time the programs read from now on (only while they are idle).
  void SetNow(Time t);
  Time now() const;
  /// Tells the programs' threads which terminal devices (st_rdev of the links' host side) are
  /// hil's links, bit k of a `touched` mask (lockstep_shared.h): a thread that waits only for
  /// links hil did not touch is not woken from then on. At most kMaxLinks; once, before a grant.
  void SetLinks(const std::vector<std::uint64_t>& rdevs);
  /// A grant to every thread: each looks at what it waits for again.
  void Wake();
  /// A grant at emulated `t` to the threads it concerns (NeedsWake): those whose deadline has
  /// come, and those waiting for descriptors of which hil touched one (`touched`: bit k for link
  /// k, kOtherFd when hil touched anything else, e.g. the CAN bus).
  void Wake(Time t, std::uint64_t touched);
  /// Waits until every claimed thread waits and has looked since the last change. False: given up.
  bool WaitIdle(const WaitStep& on_wait);
  /// One look: whether the programs are idle now.
  bool Idle() const;
  /// Whether a grant at emulated `t` can change anything for the programs: a thread runs, or one
  /// waits with a deadline at or before `t`, or one waits for descriptors among `touched`.
  bool NeedsWake(Time t, std::uint64_t touched) const;
  /// The earliest deadline of the waiting threads (none: every one waits without a timeout).
  std::optional<Time> EarliestDeadline() const;
  /// Whether the programs may have written something hil could read since the last call that
  /// said yes: a thread of theirs wrote (or closed, shut down, sent) and waited again, a thread
  /// or process ended, or hil freed a dead thread's slot (lockstep_shared.h `host_writes`).
  bool TakeHostWrites();
  /// hil paces the run the old way after all: the library passes every call through from now on
  /// (waits in progress go on as the real calls).
  void Abandon();
  /// `export LD_PRELOAD=... HIL_LOCKSTEP=...; ` for the shell line of a host (its shell does not
  /// load the library, the programs it starts do; an LD_PRELOAD of the caller's is kept after it;
  /// ASAN_OPTIONS gains verify_asan_link_order=0 so that sanitizer builds start with it).
  std::string ShellExports(const std::string& library) const;
  /// Lookahead (lockstep_advance.h): hil writes the links' chunks ahead, each published in its
  /// link's feed (the first lockstep::kFeedLinks links), and the programs move their clock
  /// themselves up to the horizon. On only while they are idle (after a turn).
  void SetLookahead(bool on);
  /// Whether a thread of the programs has waited in epoll (the library cannot follow the feeds
  /// there).
  bool EpollSeen() const;
  /// Bytes of link `k`'s feed the programs have read.
  std::uint64_t FeedConsumed(int k) const;
  /// How many more chunks not yet arrived link `k`'s feed has room for.
  std::size_t FeedFree(int k) const;
  /// Link `k`'s chunk written ahead: its last byte is byte `end_byte` of the feed (counted from
  /// the lookahead's start), and it arrives at `arrival`. After its bytes are written.
  void Publish(int k, std::uint64_t end_byte, Time arrival);
  /// Every chunk arriving at or before `t` is published (never moves back).
  void SetHorizon(Time t);
  /// Whether the programs are idle with their next move beyond the horizon.
  bool Stalled() const;
  /// Moves the programs' clock if they are idle (lockstep_advance.h MoveClock).
  void MoveClock();
  /// Waits until the programs are idle and stalled, moving their clock when they are idle and
  /// no one else does (a thread ended). False: given up.
  bool WaitStalled(const WaitStep& on_wait);
  /// The processes that have loaded the library so far.
  std::vector<Process> Processes() const;
  Stats stats() const;

 private:
  /// Threads not idle now.
  std::size_t Busy() const;
  /// Whether a grant at `t` touching `touched` concerns slot `i`.
  bool Concerns(int i, Time t, std::uint64_t touched) const;
  /// Asks slot `i`'s thread to look again.
  void Grant(int i);
  /// Frees the slots of threads that no longer exist.
  void ForgetDeadThreads();
  /// Sleeps on the host's futex until `done()` (WaitIdle, WaitStalled), moving the programs'
  /// clock when they are all idle if `move_clock_when_idle`; `on_wait` every kStep. False: given
  /// up.
  bool WaitUntil(const WaitStep& on_wait, const std::function<bool()>& done,
                 bool move_clock_when_idle);

  std::string path_;
  Shared* shared_ = nullptr;
  Stats stats_;
  std::uint64_t writes_seen_ = ~std::uint64_t{0};  ///< `host_writes` at the last TakeHostWrites
  bool slots_freed_ = false;  ///< ForgetDeadThreads freed a slot since TakeHostWrites
};

/// The library beside hil's executable (or in ../lib/ of it); empty when there is none.
std::string FindPreloadLibrary();

}  // namespace hil::harness::lockstep

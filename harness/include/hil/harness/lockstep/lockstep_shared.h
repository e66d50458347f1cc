#pragma once
/// @file
/// The memory hil shares with the programs under test that run with libhil_lockstep.so (the
/// preload library, harness/src/preload/, its contract in harness/src/preload/README.md): the
/// emulated clock hil publishes, and one slot per thread of those programs saying whether it
/// runs or waits, and until which emulated time. Header only, no allocation: the library includes
/// it too.
///
/// The protocol (every access sequentially consistent):
///  - hil writes `now_ns` (emulated time since t = 0) only while every thread waits, then bumps
///    the `seq` of each thread whose condition the change can meet and wakes its futex ("a
///    grant": bytes were written, time moved on). Which ones: a thread whose deadline has come,
///    and a thread waiting for descriptors when hil wrote to (or read from) one of the links in
///    its `links` mask, touched something outside the links (kOtherFd, e.g. the CAN bus), or
///    it waits with kEveryGrant.
///  - A thread that waits (poll, sleep, read …) marks its slot waiting with its deadline and, for
///    descriptors, the links it waits on (`link_rdev`: the links' terminal devices, published by
///    hil; any other descriptor sets kOtherFd), then bumps the `seq` of every other waiting thread
///    that what it did before may concern and wakes it: one waiting with kEveryGrant, and, when
///    it wrote since its last wait (its process's write count in /proc/self/io, or a close,
///    shutdown or send), one waiting for descriptors with kOtherFd or in the same process. Then it
///    loops: load its own `seq` → c, look at its condition without blocking (its descriptors, its
///    deadline against `now_ns`), return if met, else store c in `acked` and sleep on its `seq`
///    futex while that still holds c.
///  - The programs are idle when every claimed slot waits with `acked == seq`: every thread has
///    looked at its condition since the last change that concerns it and found it unmet. Only
///    then does hil read what they wrote (at the emulated time `now_ns`) or move time on, to the
///    earliest of its own next event and the slots' deadlines.
/// A process that loads the library claims its main thread's slot (running) before it lists itself
/// in `processes`: hil, which starts its first turn once the hosts are listed, never finds a
/// program that is still starting idle, however long the machine keeps it from running.
/// When `passthrough` is set every call is the real one (waits in progress go on the real way).
/// A thread that goes to wait after it wrote (as above) bumps `host_writes` first; so does a
/// thread or process that ends: hil reads the links at a turn only when `host_writes` moved.
/// A thread bumps `host_wake` when it waits or acknowledges, and wakes its futex when hil says it
/// sleeps on it (`hil_waiting`) and the programs are idle after its acknowledgement (of threads
/// acknowledging at once, the last one in the sequentially consistent order sees the others').

#include <atomic>
#include <cstdint>

namespace hil::harness::lockstep {

/// The environment variable that names the shared file (set by hil for the programs it starts).
inline constexpr const char* kEnvFile = "HIL_LOCKSTEP";
inline constexpr std::uint32_t kMagic = 0x4b434c48;  // "HLCK"
inline constexpr std::uint32_t kVersion = 5;
/// Threads (of every program of a run together) and processes the file has room for.
inline constexpr int kMaxThreads = 256;
inline constexpr int kMaxProcesses = 32;
/// Links hil tells apart in a thread's `links` mask (bits 0–61); bit kOtherFd: any other
/// descriptor (a pipe, a socket, a link beyond these, one that cannot be identified); bit
/// kEveryGrant: one whose readiness hil's own threads may change at any time (output to a pipe
/// hil reads, an epoll set whose descriptors are not known), set in every grant's mask.
inline constexpr int kMaxLinks = 62;
inline constexpr std::uint64_t kEveryGrant = std::uint64_t{1} << 62;
inline constexpr std::uint64_t kOtherFd = std::uint64_t{1} << 63;
inline constexpr std::uint64_t kAnything = ~std::uint64_t{0};
/// A deadline that never comes.
inline constexpr std::int64_t kNoDeadline = INT64_MAX;
/// CLOCK_MONOTONIC and CLOCK_BOOTTIME read emulated time plus this (a parameter of ours: a
/// machine that booted 1000 s ago, so that a program taking a zero time stamp for "never", as
/// PX4's drivers do, sees none).
inline constexpr std::int64_t kMonotonicBaseNs = 1'000'000'000'000;

enum SlotState : std::uint32_t { kRunning = 0, kWaiting = 1 };

struct alignas(64) ThreadSlot {
  std::atomic<std::int32_t> tid;  ///< 0: free
  std::atomic<std::int32_t> pid;
  std::atomic<std::uint32_t> state;
  std::atomic<std::uint32_t> seq;         ///< futex word it sleeps on; bumped: look again
  std::atomic<std::uint32_t> acked;       ///< the `seq` its condition was last found unmet at
  std::atomic<std::int64_t> deadline_ns;  ///< emulated; kNoDeadline: none
  std::atomic<std::uint64_t> waits;       ///< waits that blocked (statistics)
  std::atomic<std::uint64_t> looks;       ///< conditions found unmet and acknowledged (statistics)
  /// 1 while it waits for descriptors (poll, select, epoll, read), 0 in a sleep: bytes hil
  /// writes cannot end a sleep, so they need not wake a program whose threads all sleep
  std::atomic<std::uint32_t> on_descriptors;
  /// while it waits for descriptors: bit k for link k (`link_rdev`), kOtherFd for any other
  std::atomic<std::uint64_t> links;
};

/// Lookahead (lockstep_advance.h): hil writes a link's chunks before their arrival and says here
/// when each arrives; the programs' threads read only what has arrived and move the clock
/// themselves. The first kFeedLinks links have a feed; each holds kFeedEntries chunks not yet
/// arrived (a power of two: the ring's index is the count modulo it).
inline constexpr int kFeedLinks = 16;
inline constexpr int kFeedEntries = 512;

/// One chunk written ahead: the link's byte count after its last byte, and its emulated arrival.
struct FeedEntry {
  std::atomic<std::uint64_t> end_byte;
  std::atomic<std::int64_t> arrival_ns;
};

/// A link's chunks written ahead (byte counts from the start of the lookahead).
struct LinkFeed {
  std::atomic<std::uint64_t> published;        ///< entries ever published (hil)
  std::atomic<std::uint64_t> arrived_entries;  ///< of these, arrived by `now_ns`
  std::atomic<std::uint64_t> arrived_bytes;    ///< the last arrived entry's end_byte
  std::atomic<std::uint64_t> consumed;         ///< bytes the programs have read (the library)
  FeedEntry ring[kFeedEntries];
};

struct ProcessEntry {
  std::atomic<std::int32_t> pid;  ///< 0: free
  char comm[16];                  ///< its name (/proc/self/comm), NUL-terminated
};

struct Shared {
  std::uint32_t magic;
  std::uint32_t version;
  std::int64_t utc_epoch_ns;  ///< CLOCK_REALTIME at emulated t = 0 (the scenario's start)
  std::atomic<std::int64_t> now_ns;
  std::atomic<std::uint32_t> host_wake;  ///< futex word hil sleeps on
  std::atomic<std::uint32_t> hil_waiting;
  /// bumped by a thread that wrote (or closed, shut down, sent) since its last wait, when it
  /// waits again, and by a thread or process that ends: what hil could read may have changed
  std::atomic<std::uint64_t> host_writes;
  /// Set by hil when it paces the run the old way after all (a host process did not load the
  /// library in time): every call is the real one from then on, waits in progress end.
  std::atomic<std::uint32_t> passthrough;
  std::atomic<std::int32_t> slots_used;  ///< slots[0, slots_used) have been claimed at some time
  std::atomic<std::int32_t> processes_used;
  /// the links' terminal devices (st_rdev of their host side), set by hil once before it first
  /// tells threads apart by them; until then every descriptor counts as kOtherFd
  std::atomic<std::int32_t> link_count;
  std::uint64_t link_rdev[kMaxLinks];
  /// 1 while hil writes ahead (lockstep_advance.h): reads and readiness of a link with a feed
  /// follow the feed, and the thread whose acknowledgement makes the programs idle moves `now_ns`
  /// to the next arrival or deadline up to `horizon_ns` itself.
  std::atomic<std::uint32_t> lookahead;
  /// every chunk that arrives at or before this (emulated ns) is in the feeds
  std::atomic<std::int64_t> horizon_ns;
  std::atomic<std::uint32_t> advancing;  ///< 1 while one party moves the clock (a spin lock)
  /// 1 when the programs were idle and their next arrival or deadline lay beyond the horizon
  std::atomic<std::uint32_t> stalled;
  std::atomic<std::uint64_t> advances;  ///< clock moves that woke a thread (statistics)
  /// set by the library when a thread waits in epoll (whose descriptors it cannot tell apart)
  std::atomic<std::uint32_t> epoll_seen;
  /// descriptors the library told apart with fstat (statistics: with its per-process cache, once
  /// per descriptor and link opened, not once per wait; harness/src/preload/descriptor_cache.h)
  std::atomic<std::uint64_t> descriptor_lookups;
  LinkFeed feeds[kFeedLinks];
  ThreadSlot slots[kMaxThreads];
  ProcessEntry processes[kMaxProcesses];
};

}  // namespace hil::harness::lockstep

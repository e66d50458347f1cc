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
///    `change` and wakes its futex ("a grant": bytes were written, time moved on).
///  - A thread that waits (poll, sleep, read …) marks its slot waiting and bumps `change` (what it
///    wrote before may be what another thread waits for), then loops: load `change` → c, look at
///    its condition without blocking (its descriptors, its deadline against `now_ns`), return if
///    met, else store c in `acked` and sleep on the `change` futex while it still holds c.
///  - The programs are idle when every claimed slot waits with `acked == change`: every thread has
///    looked at its condition since the last change and found it unmet. Only then does hil read
///    what they wrote (at the emulated time `now_ns`) or move time on, to the earliest of its own
///    next event and the slots' deadlines.
/// When `passthrough` is set every call is the real one (waits in progress go on the real way).
/// A thread bumps `host_wake` when it waits or acknowledges, and wakes its futex when hil says it
/// sleeps on it (`hil_waiting`).

#include <atomic>
#include <cstdint>

namespace hil::harness::lockstep {

/// The environment variable that names the shared file (set by hil for the programs it starts).
inline constexpr const char* kEnvFile = "HIL_LOCKSTEP";
inline constexpr std::uint32_t kMagic = 0x4b434c48;  // "HLCK"
inline constexpr std::uint32_t kVersion = 1;
/// Threads (of every program of a run together) and processes the file has room for.
inline constexpr int kMaxThreads = 256;
inline constexpr int kMaxProcesses = 32;
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
  std::atomic<std::uint32_t> acked;       ///< the `change` its condition was last found unmet at
  std::atomic<std::int64_t> deadline_ns;  ///< emulated; kNoDeadline: none
  std::atomic<std::uint64_t> waits;       ///< waits that blocked (statistics)
  /// 1 while it waits for descriptors (poll, select, epoll, read), 0 in a sleep: bytes hil
  /// writes cannot end a sleep, so they need not wake a program whose threads all sleep
  std::atomic<std::uint32_t> on_descriptors;
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
  std::atomic<std::uint32_t> change;     ///< futex word the threads sleep on
  std::atomic<std::uint32_t> host_wake;  ///< futex word hil sleeps on
  std::atomic<std::uint32_t> hil_waiting;
  /// Set by hil when it paces the run the old way after all (a host process did not load the
  /// library in time): every call is the real one from then on, waits in progress end.
  std::atomic<std::uint32_t> passthrough;
  std::atomic<std::int32_t> slots_used;  ///< slots[0, slots_used) have been claimed at some time
  std::atomic<std::int32_t> processes_used;
  ThreadSlot slots[kMaxThreads];
  ProcessEntry processes[kMaxProcesses];
};

}  // namespace hil::harness::lockstep

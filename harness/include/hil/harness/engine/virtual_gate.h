#pragma once
/// @file
/// Virtual mode's pacing of the host: the order in which the estimator under test sees its links'
/// bytes is the order of emulated time, whatever the machine's load.
///
/// Before bytes go to one link the estimator reads, it has read every byte already written to its
/// other links (exactly: SerialPort::PendingToHost() is 0 on them, bytes still in the kernel's pty
/// hand-over included). So a host that decodes what it reads as it reads it sees the same sequence
/// of messages across its links in every run: an IMU frame written before a GNSS sentence is read
/// before it, never after. Runs of bytes on one link wait only for that link's backlog to fall
/// below `max_link_backlog_bytes` (which bounds the pty buffer, not the order).
///
/// Host-to-device bytes get emulated times as deterministic as device-to-host ones: at the
/// engine's host turns (virtual_host_turns.h) WaitHostIdle() holds emulated time until the host has
/// read every byte written so far and every thread of its process group sleeps. It has then
/// answered all it read, or waits for more; what it wrote is read at the turn's emulated time. Its
/// answer cannot depend on bytes written later (there are none yet), nor on when the machine ran
/// it.
///
/// While it waits, `on_wait` is called (it polls the estimator's output and decides when a host
/// that no longer reads has hung); returning false gives up the wait and the run.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/dut/process_group.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {

class VirtualGate {
 public:
  /// Called on every wait step with the bytes still unread on the links waited for and whether
  /// this step starts a new wait. Returns false to abandon the wait.
  using WaitStep = std::function<bool(std::size_t unread, bool new_wait)>;

  /// `host_pgid`: the host's process group, whose sleep WaitHostIdle() waits for (≤ 0: none,
  /// WaitHostIdle() then waits only for the bytes to be read).
  /// `max_skew`: 0, the other links read to their last byte before bytes go to one link; above 0
  /// (a host that orders its inputs by device time itself, e.g. navd's [input] merge_window_s),
  /// only their bytes made up to `max_skew` before the last of these bytes (see BeforeWrite).
  VirtualGate(std::vector<SerialEndpoint*> host_links, std::size_t max_link_backlog_bytes,
              WaitStep on_wait, int host_pgid = -1, Duration max_skew = Duration{0});

  /// Before `bytes` bytes are written to `ep`: waits until the host has read the other host links
  /// and `ep`'s backlog leaves room. Links the host does not read pass at once. False: the wait
  /// was given up (the run stops). With a max_skew, `t_first` and `t_last` are the emulated
  /// times the first and the last of these bytes were made at, and of the other links only the
  /// bytes made up to t_last − max_skew must have been read (a run of bytes counts as made at
  /// its first byte's time until all of it is read).
  bool BeforeWrite(const SerialEndpoint& ep, std::size_t bytes, Time t_first = Time{},
                   Time t_last = Time{});
  /// BeforeWrite without the wait: true (and the bytes counted) when they may go now. With a
  /// max_skew, a link refused is not asked about again for kRetryAfterRefusal of wall time (the
  /// run calls this at every event, and each answer costs a system call per other link: 81 000
  /// of them, 15 % of the main thread's time, in seed004); the bytes then wait a little longer,
  /// and the host, which orders them by device time itself, reads the same data.
  bool TryWrite(const SerialEndpoint& ep, std::size_t bytes, Time t_first = Time{},
                Time t_last = Time{});
  Duration max_skew() const { return max_skew_; }
  /// Whether the host reads `ep` (one of the links given at construction).
  bool Reads(const SerialEndpoint& ep) const;
  /// The host no longer reads `ep` (its reader, a closed loop's controller, has ended): the gate
  /// neither waits for its bytes to be read nor orders the other links after them.
  void StopReading(const SerialEndpoint& ep);
  /// Waits while a link the host reads has no room: calls `write_more` (it writes what the link
  /// takes and returns the bytes still to write) until it returns 0, the run's watchdog seeing
  /// those bytes as unread. False: the wait was given up (the run stops).
  bool WaitForRoom(const std::function<std::size_t()>& write_more);
  /// Waits until the host has read every byte of every link it reads.
  bool WaitAllRead();
  /// Bytes not yet read on the host links (exact when 0), for the drain and hang reports.
  std::size_t Unread();
  /// Waits until the host has read every byte and all its threads sleep (a host turn). A host
  /// that has read everything but does not sleep within `kBusyHostLimit` of wall time (it
  /// polls without blocking) cannot be waited for: from then on the turns wait only for its
  /// reads, and busy_host() says so. False: the wait was given up (the run stops).
  bool WaitHostIdle();
  /// After the first host turn: no process of the host's group holds a host link open for
  /// writing (it opened them O_RDONLY, as navd does where it sends nothing): the host cannot
  /// write what a turn waits for, so the periodic host turns need not wait for it.
  bool HostReadsOnly() const { return writes_scanned_ && !host_writes_; }
  /// Bytes came from a host that held its links read-only (it opened one for writing since):
  /// HostReadsOnly() is false from now on, and a message says that this once the turn that read
  /// them depended on the machine.
  void NoteHostWrote();
  /// The host was found never to sleep (its host-to-device bytes are then stamped when they are
  /// seen, not deterministically).
  bool busy_host() const { return busy_host_; }
  /// A host that has read everything but is not asleep this long (wall) is a busy host.
  static constexpr Duration kBusyHostLimit = std::chrono::seconds(2);
  /// With a max_skew: how long (wall) TryWrite refuses a link it refused without asking again.
  static constexpr Duration kRetryAfterRefusal = std::chrono::microseconds(50);
  /// The host's first turn waits also until a process of its group holds every host link open
  /// (a host that is still starting may sleep before it has opened its devices and written its
  /// start-up commands), at most this long (wall): a loaded machine (a parallel test suite, a TCG
  /// VM beside) took navd over 2 s, and its first UBX command then came a turn late; below the
  /// silence timeout's default (10 s), which would end the run as a hang.
  static constexpr Duration kHostStartLimit = std::chrono::seconds(6);
  /// How often (wall) that first turn looks for the host's descriptors while it waits.
  static constexpr Duration kHostScanPeriod = std::chrono::milliseconds(1);

 private:
  struct Link {
    const SerialEndpoint* ep;
    // ≥ the bytes unread: 0 when the kernel last said 0, else what was written since (Ask)
    std::size_t unread_bound;
    std::size_t seen_unread = 0;  // ≤ the bytes unread: the kernel's last count (waits' progress)
    // with a max_skew: the bytes written so far, and the runs not known to be read yet (the
    // byte count at their end, the time of their first byte)
    std::size_t written = 0;
    std::deque<std::pair<std::size_t, Time>> runs{};
    bool read = true;       // false once its reader has gone (StopReading): no order kept for it
    WallTime refused_at{};  // when TryWrite last refused (with a max_skew)
  };
  /// With a max_skew: whether the host has read every other link's bytes made up to `t`.
  bool OthersReadUpTo(const Link* self, Time t);
  void Counted(Link& self, std::size_t bytes, Time t_first);
  Link* Find(const SerialEndpoint& ep);
  /// Unread bytes on the links selected (refreshing their bounds); `except` is skipped, and a
  /// link known to be read (bound 0) is not asked again unless `ask_all`.
  std::size_t Refresh(const Link* except, const Link* only, bool ask_all = false);
  /// Asks the kernel about `l`'s unread bytes (see the bounds in Link).
  void Ask(Link& l);
  bool Wait(const std::function<bool()>& done, const Link* except, const Link* only);

  std::vector<Link> links_;
  std::size_t max_backlog_;
  WaitStep on_wait_;
  /// Whether a process of the host's group has every host link open, and whether one holds a
  /// host link open for writing.
  struct LinkHolding {
    bool all_held;
    bool writable;
  };
  LinkHolding ScanHostLinks() const;

  Duration max_skew_{0};
  std::optional<GroupSleepProbe> host_;
  int host_pgid_ = -1;
  bool busy_host_ = false;
  bool links_opened_ = false;
  bool writes_scanned_ = false;  // the first WaitHostIdle() has looked at the host's descriptors
  bool host_writes_ = true;      // a host link is open for writing (or the host could not be seen)
};

}  // namespace hil::harness

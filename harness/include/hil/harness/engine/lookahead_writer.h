#pragma once
/// @file
/// `hil run --lockstep` with lookahead (issue 42): hil writes the links' bytes ahead of the
/// programs' clock instead of one host turn per message. Each chunk written is published in its
/// link's feed with its arrival time (lockstep_advance.h); the preload library lets the programs
/// read a chunk only once their clock has reached its arrival, and moves their clock itself from
/// arrival to arrival (and to their deadlines) up to the horizon, the time up to which every
/// arrival is published. So the programs see exactly what one turn per message would show them,
/// in every run, while hil goes on with the next events on its own CPU.
///
/// Only where nothing a program does can reach a device: an open loop whose programs hold every
/// link read-only, without a CAN bus (ClockedHostTurns decides; a program's write would need the
/// device to take it at an emulated time hil has passed).

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "hil/firmware_emu/sim_time.h"
#include "hil/harness/links/serial_endpoint.h"
#include "hil/harness/lockstep/lockstep_host.h"

namespace hil::harness {

class LookaheadWriter {
 public:
  /// `links`: the links in the order of their feeds (ClockedPacer::endpoints, at most
  /// lockstep::kFeedLinks); `on_wait`: the run's watchdog while hil waits for the programs.
  LookaheadWriter(lockstep::LockstepHost& host, std::vector<SerialEndpoint*> links,
                  lockstep::LockstepHost::WaitStep on_wait);

  /// Before the events at `t`: every chunk arriving before `t` has been made. The chunks are
  /// written and published when the programs have caught up with the horizon (they wait for it)
  /// or a link holds kBatchBytes; hil waits for the programs when a link holds kHoldBytes that
  /// it could not write (kAheadBytes unread already). False: the wait was given up.
  bool Step(Time t);
  /// After the last event: writes everything, moves the horizon to `t` and waits until the
  /// programs have reached it. False: the wait was given up.
  bool Finish(Time t);
  /// Writes (system calls) so far.
  std::uint64_t writes() const { return writes_; }

  /// A link's bytes that gather before they are written when the programs do not wait for them
  /// (our choice: 2 KB, a few hundred ms of a 115 200 Bd link, one write instead of dozens).
  static constexpr std::size_t kBatchBytes = 2048;
  /// At most this many bytes of a link written and not yet read by the programs (our choice:
  /// 6 KB; a pty holds about 12 KB, the line discipline's 4095 bytes and 8 KB of flip buffers
  /// that the kernel counts with its allocation overhead, and a write beyond drops bytes).
  static constexpr std::size_t kAheadBytes = 6144;
  /// hil waits for the programs when a link holds this many bytes it could not write.
  static constexpr std::size_t kHoldBytes = 65536;

 private:
  /// Writes each link's waiting chunks while they fit (kAheadBytes, a free feed entry; `force`:
  /// a free feed entry only) and publishes them; the horizon moves to `horizon`, or to just
  /// before the first chunk left waiting.
  void Publish(Time horizon, bool force);
  /// Link `k`'s part of Publish; returns the end of its first chunk left waiting, if any.
  std::optional<Time> PublishLink(std::size_t k, bool force);
  /// After the programs caught up with the horizon: Publish, and if nothing fitted, Publish
  /// regardless of room. Whether anything was written.
  bool WriteWhatFits(Time horizon);
  /// The most bytes a link holds unwritten (counted as chunks join: SerialEndpoint::queued_bytes
  /// walks the whole queue, a quarter of hil's time when the programs lag behind).
  std::size_t MostQueued();

  lockstep::LockstepHost& host_;
  std::vector<SerialEndpoint*> links_;
  lockstep::LockstepHost::WaitStep on_wait_;
  std::vector<std::uint64_t> written_;  ///< per link: bytes written since the lookahead began
  std::vector<std::size_t> queued_;     ///< per link: bytes of its first counted_ waiting chunks
  std::vector<std::size_t> counted_;    ///< per link: waiting chunks counted in queued_
  std::vector<std::pair<std::uint64_t, Time>> batch_;  ///< one link's chunks: end byte, arrival
  std::uint64_t writes_ = 0;
};

}  // namespace hil::harness

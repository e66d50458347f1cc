#pragma once
/// @file
/// Host turns (host_turns.h) for programs that run on hil's clock through the preload library
/// (`hil run --lockstep`; lockstep_host.h, clocked_pacer.h). Instead of asking /proc whether the
/// host sleeps, hil reads the programs' own account in shared memory: every thread says when it
/// waits, for what and until which emulated time.
///
/// A turn happens at the earliest of the end of a chunk of device bytes (they reach the host
/// then) and the programs' earliest wake-up deadline, when that comes before (or at) the next
/// device event: hil sets the programs' clock to that time, writes the chunks that have ended,
/// wakes the programs and waits until every thread waits again. What they wrote meanwhile is read
/// at that emulated time (the time of the write: the clock did not move while they ran) and
/// reaches its device at once. The first turn, at t = 0, waits for the programs' start-up. A
/// program that writes, sleeps 250 ms or times out a poll thus does so at the same emulated time
/// in every run, whatever the machine's load.
///
/// With lookahead allowed (an open loop without a CAN bus) and, after the first turn, every link
/// held read-only by the programs, none of which has waited in epoll, there are no more turns
/// per message: a LookaheadWriter writes the bytes ahead and the programs move their own clock
/// from arrival to arrival (lookahead_writer.h); the drain is a turn as before.

#include <cstdint>
#include <optional>

#include "hil/harness/engine/clocked_pacer.h"
#include "hil/harness/engine/host_arrivals.h"
#include "hil/harness/engine/host_turns.h"
#include "hil/harness/engine/lookahead_writer.h"
#include "hil/harness/lockstep/lockstep_host.h"
#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness {

class ClockedHostTurns final : public HostTurns {
 public:
  /// `on_wait`: called while hil waits for the programs (the run's watchdog); false gives up.
  ClockedHostTurns(lockstep::LockstepHost& host, ClockedPacer& pacer,
                   lockstep::LockstepHost::WaitStep on_wait, bool lookahead_allowed = false);

  Time NextAction() const override;
  /// Host bytes or a bus frame reaching a device, then a turn, due before (or at) the event.
  bool BeforeEvent(Time t_event, Time t_end, EngineMonitor& monitor, DeviceIo& io,
                   DeviceOutput& out) override;
  /// Nothing: the hosts are read at turns only.
  void AfterEvent(Time t_event, DeviceIo& io, DeviceOutput& out) override {
    (void)t_event, (void)io, (void)out;
  }
  /// After the run: the turns due before the end of the last byte (each chunk written at its
  /// end, or the lookahead writer's), then one last turn there, so the programs read everything.
  /// False when the wait was given up.
  bool Drain(DeviceIo& io) override;
  /// Whether hil writes ahead (decided after the first turn).
  bool lookahead() const { return lookahead_.has_value(); }

 private:
  /// The next turn's time: the earliest chunk end or deadline (none: no turn is due).
  std::optional<Time> NextTurn() const;
  /// A turn at `t`: the programs are woken when that can change anything for them (see
  /// LockstepHost::NeedsWake), always with `wake` (the first turn: they ran from their start;
  /// the drain: Flush wrote what was left). False when the wait was given up.
  bool Turn(Time t, DeviceIo& io, bool wake = false);
  /// After the first turn: writes ahead from now on if allowed and the programs can neither
  /// write to a link nor wait where the library cannot follow the feeds.
  void MaybeLookAhead();
  /// The bit of `ep` in the grants' masks (lockstep_shared.h).
  std::uint64_t LinkBitOf(const SerialEndpoint* ep) const;

  lockstep::LockstepHost& host_;
  ClockedPacer& pacer_;
  lockstep::LockstepHost::WaitStep on_wait_;
  bool started_ = false;
  bool lookahead_allowed_ = false;
  std::optional<LookaheadWriter> lookahead_;
  bool epoll_noted_ = false;
  /// what hil touched since the last grant (lockstep_shared.h's mask): links written or read, the
  /// bus (kOtherFd); a grant adds kEveryGrant
  std::uint64_t touched_ = 0;
  HostArrivals arrivals_;  // host bytes and others' frames read at turns, not yet delivered
};

}  // namespace hil::harness

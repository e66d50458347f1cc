#pragma once
/// @file
/// Virtual mode with the programs under test on hil's clock (pacer.h; `hil run --lockstep`, the
/// preload library harness/src/preload/): emulated time runs free, and the bytes a device makes
/// reach the host when the last byte of their chunk has left the UART, not when they are made. The
/// host turns (clocked_host_turns.h) move the programs' clock to that time, write the chunks due
/// (WriteDue) and wake the programs, so a program that stamps what it reads with clock_gettime
/// sees the emulated arrival times of the bytes. CAN frames go when they are made, as in virtual
/// mode.

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "hil/harness/engine/pacer.h"

namespace hil::harness {

class ClockedPacer final : public Pacer {
 public:
  Stepping stepping() const override { return Stepping::kVirtual; }
  void Start(EngineDevices& devices) override;
  /// Emulated time does not wait for the wall clock.
  bool Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) override {
    (void)step, (void)io, (void)out;
    return false;
  }
  /// The bytes wait in their endpoint until WriteDue.
  void Queued(SerialEndpoint& ep, std::size_t bytes, Time t_ready) override {
    (void)ep, (void)bytes, (void)t_ready;
  }
  bool Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) override;
  /// Nothing: the drain's turns write what still waits, each chunk at its end, or the lookahead
  /// writer does (ClockedHostTurns::Drain).
  bool Flush(DeviceIo& io) override;

  /// The earliest end of a chunk still waiting, if any.
  std::optional<Time> NextChunkEnd() const;
  /// Writes every waiting chunk that has ended by `t`, and waits until the kernel has handed them
  /// to the host's side of the pty (see kHandOverBytes). Returns the links written: bit k for
  /// the k-th link of LinkDevices (lockstep_shared.h's mask; kOtherFd for those beyond kMaxLinks).
  /// What the host side held before the write is one ioctl when the last hand-over on the link
  /// was complete (settled_), else SerialEndpoint::PendingToHost (which waits for a hand-over).
  std::uint64_t WriteDue(Time t);
  /// The terminal device (st_rdev) of each link's host side, in the order of WriteDue's bits (0:
  /// none, a link that is not a terminal): what LockstepHost::SetLinks takes, before the hosts
  /// start (so that a thread's first wait already tells the links apart, in every run alike).
  static std::vector<std::uint64_t> LinkDevices(
      const std::vector<std::vector<std::unique_ptr<SerialEndpoint>>>& endpoints);
  /// The bit of the `k`-th link in WriteDue's mask.
  static std::uint64_t LinkBit(std::size_t k);
  /// The links, in the order of WriteDue's bits.
  const std::vector<SerialEndpoint*>& endpoints() const { return endpoints_; }
  /// Whether CAN frames were sent since the last call.
  bool TakeBusWritten() { return std::exchange(bus_written_, false); }
  /// What the host side's line discipline holds at most (N_TTY's buffer, 4 KB, less one): the
  /// bytes beyond it stay in the pty's flip buffers, so how a backlog larger than this is split
  /// among the host's reads depends on the machine.
  static constexpr std::size_t kHandOverBytes = 4095;
  /// How long (wall) WriteDue waits for the kernel's hand-over before it goes on.
  static constexpr Duration kHandOverLimit = std::chrono::milliseconds(100);

 private:
  /// What the host side of link `k` held before a write: exact, as PendingToHost, in one look
  /// when the link is settled.
  std::size_t HeldBefore(std::size_t k) const;

  std::vector<SerialEndpoint*> endpoints_;
  /// per link: its bytes_sent() when every byte written had reached the host side (the last
  /// hand-over ended within kHandOverBytes, nothing dropped or written since), else kUnsettled
  std::vector<std::uint64_t> settled_;
  static constexpr std::uint64_t kUnsettled = ~std::uint64_t{0};
  bool bus_written_ = false;
};

}  // namespace hil::harness

#pragma once
/// @file
/// Free-running virtual time (pacer.h): no wall clock; every byte is written when it is made,
/// through the virtual write queue, which keeps the host's links in emulated-time order when a
/// gate is used (virtual_gate.h). Without a gate (no host is paced) bytes go as they are made.

#include <cstddef>

#include "hil/harness/engine/pacer.h"
#include "hil/harness/engine/virtual_write_queue.h"

namespace hil::harness {

class VirtualPacer : public Pacer {
 public:
  /// The bytes the run may hold back before it writes them whatever the gate says.
  static constexpr std::size_t kMaxDeferredBytes = 8192;

  Stepping stepping() const override { return Stepping::kVirtual; }
  /// A paced host reads its links in runs of messages: the last run may wait for more.
  void UseGate(VirtualGate& gate) override {
    writes_ = VirtualWriteQueue(&gate, kMaxDeferredBytes);
    hold_tail_ = true;
  }
  bool Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) override;
  void Queued(SerialEndpoint& ep, std::size_t bytes, Time t_ready) override {
    writes_.Add(ep, bytes, t_ready);
  }
  bool Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) override;
  bool SendAll() override { return writes_.Pump(true); }
  bool Flush(DeviceIo& io) override;

 private:
  VirtualWriteQueue writes_{nullptr, kMaxDeferredBytes};
  bool hold_tail_ = false;
};

}  // namespace hil::harness

#pragma once
/// @file
/// Virtual mode's write path (engine/virtual_pacer.h): the chunks queued on the serial endpoints,
/// written in emulated-time order through the gate (virtual_gate.h) that keeps the host's links in
/// order.

#include <cstddef>
#include <deque>
#include <optional>

#include "hil/harness/engine/virtual_gate.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {

/// Virtual mode's writes: every chunk queued on a serial endpoint, in emulated-time order across
/// links. Consecutive chunks of one link form a batch that goes out in one write. A batch goes as
/// soon as the gate lets it through without waiting and it is complete: a chunk of another link
/// follows it, or it holds `kBatchBytes` (with `hold_tail` false, also the last batch, which may
/// still grow). So the host reads its links in runs of messages, in the same order across links
/// as message by message (a batch of one link never passes a chunk of another), with a write, a
/// wake-up and a read per run instead of per message. While the host keeps up the run never waits
/// for it; when more than `max_deferred_bytes` wait here, Pump waits for the host.
/// Without a gate (no estimator to pace) every chunk is written at once.
class VirtualWriteQueue {
 public:
  VirtualWriteQueue(VirtualGate* gate, std::size_t max_deferred_bytes)
      : gate_(gate), max_deferred_(max_deferred_bytes) {}
  /// One chunk of `bytes` bytes made at emulated time `t` was queued on `ep`
  /// (SerialEndpoint::Queue returned true).
  void Add(SerialEndpoint& ep, std::size_t bytes, Time t = Time{});
  /// Writes what may go; with `all`, waits for the host until everything is written. False: the
  /// gate gave up a wait (the run stops; the rest stays unsent). `hold_tail`: the last batch
  /// waits for the next chunk of another link (or kBatchBytes) unless `all`.
  bool Pump(bool all, bool hold_tail = false);
  /// The bytes at which a batch of one link goes even without a chunk of another link after it.
  static constexpr std::size_t kBatchBytes = 2048;
  /// The same with a max_skew, and what may then wait here is 4 of them. Every write to a pty
  /// wakes the kernel worker that hands its bytes over, and the worker's wake-up preempts the
  /// writer: beside busy processes each preemption cost the run a wait for a CPU (seed004 beside
  /// two busy loops: 4.1–4.4 s with 2048-byte batches, 3.3–3.6 s with these; quiet the same).
  static constexpr std::size_t kSkewBatchBytes = 8192;
  std::size_t deferred_bytes() const { return deferred_; }

 private:
  struct Batch {
    SerialEndpoint* ep;
    std::size_t chunks;
    std::size_t bytes;
    Time t_first, t_last;
  };
  /// With a max_skew: the batches at the front that lie within it, each link's runs in one
  /// write; `forced`, waiting for the host, else only the links the gate lets through now.
  /// Whether any went (nullopt: the gate gave up a wait).
  std::optional<bool> PumpFrontPerLink(bool forced);
  /// Writes a batch; a link the host reads waits for room instead of dropping (WaitForRoom).
  /// False: the wait was given up.
  bool Write(const Batch& b);
  VirtualGate* gate_;
  std::size_t max_deferred_;
  std::deque<Batch> fifo_;
  std::size_t deferred_ = 0;
};

}  // namespace hil::harness

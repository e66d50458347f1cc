#pragma once
/// @file
/// Byte-level faults of the fault timeline applied to whole serial messages before they enter the
/// UART queue: `frame_drop` removes a message (with its probability), `byte_corruption` flips one
/// random bit in each byte with its per-byte probability. The random stream is seeded from the run
/// seed and consumed in message order, so the bytes are identical in every run mode.

#include <cstdint>
#include <random>
#include <string>

#include "hil/firmware_emu/device.h"
#include "hil/harness/fault_timeline.h"

namespace hil::harness {

class ByteFaultInjector {
 public:
  ByteFaultInjector(const FaultTimeline& timeline, std::uint64_t seed);

  /// Applies the faults active at `msg.t_ready` on `link`. Returns false when the message is dropped.
  bool Apply(SerialMessage& msg, const std::string& link);

  std::uint64_t messages_dropped() const { return dropped_; }
  std::uint64_t bytes_corrupted() const { return corrupted_; }

 private:
  const FaultTimeline& timeline_;
  std::mt19937_64 rng_;
  std::uint64_t dropped_ = 0, corrupted_ = 0;
};

}  // namespace hil::harness

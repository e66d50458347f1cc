#pragma once
/// @file
/// Link faults of the fault timeline applied to whole serial messages before they enter the UART
/// queue, and to CAN frames before they reach the bus:
///   - `frame_drop` removes a message (with its probability);
///   - `frame_truncate` cuts a message at a uniformly drawn byte (with its probability);
///   - `byte_corruption` flips one random bit in each byte with its per-byte `probability`, or
///   every
///     bit independently with its `bit_error_rate`;
///   - `baud_mismatch` replaces the message by what the host UART reads when the device sends at
///   the
///     fault's `baud` (uart_baud_mismatch.h);
///   - `frame_duplicate` sends the message twice (with its probability);
///   - `can_reorder` swaps two consecutive CAN frames of one device output (with its probability),
///     each keeping the other's bus time, so the bus sees them in the wrong order.
/// The random stream is seeded from the run seed and consumed in message order, so the bytes are
/// identical in every run mode. Each injection is noted in the FaultRecorder, if one is given.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/scenario/fault_timeline.h"

namespace hil::harness {

class ByteFaultInjector {
 public:
  ByteFaultInjector(const FaultTimeline& timeline, std::uint64_t seed,
                    FaultRecorder* recorder = nullptr);

  /// Applies the faults active at `in.t_ready` on `link` and appends what the link carries to
  /// `out`: nothing (dropped), the message, or two copies (duplicated). `link_baud` is the host's
  /// baud (for baud_mismatch; 0 disables that fault).
  void Process(const SerialMessage& in, const std::string& link, int link_baud,
               std::vector<SerialMessage>& out);
  /// Process() without baud mismatch and duplicates, in place. Returns false when the message is
  /// dropped.
  bool Apply(SerialMessage& msg, const std::string& link);
  /// Applies can_reorder to the frames of one device output.
  void ProcessCan(std::vector<CanFrame>& frames);

  std::uint64_t messages_dropped() const { return dropped_; }
  std::uint64_t bytes_corrupted() const { return corrupted_; }

 private:
  bool DropTruncateCorrupt(SerialMessage& msg, const std::string& link);
  void Note(std::optional<std::size_t> index, Time t, std::uint64_t n = 1);

  const FaultTimeline& timeline_;
  FaultRecorder* recorder_;
  std::mt19937_64 rng_;
  std::uint64_t dropped_ = 0, corrupted_ = 0;
};

}  // namespace hil::harness

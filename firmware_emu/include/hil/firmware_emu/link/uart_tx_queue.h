#pragma once
/// @file
/// @system
/// name: UartTxQueue (a device's UART transmitter with its transmit buffer)
/// input: whole messages, each ready at an emulated time
/// output: TimedChunk — the message's bytes with the emulated time of each byte's start bit
/// rate: drained at the configured baud, `bits_per_byte` bit times per byte (10 for 8N1)
/// @endsystem
///
/// A message that does not fit the free space of the transmit buffer at the time it becomes ready
/// is dropped whole, as a u-blox receiver drops it ("the receiver does not check whether a message
/// will be transmitted completely"; messages are never truncated), and counted.
///
/// Answers to the host go ahead of what has not begun (SubmitAhead): the transmitter takes whole
/// messages, one at a time, and a reply ready while periodic output waits goes after the message
/// on the wire, before the rest. The model's choice (no u-blox document says how the receiver
/// orders its port's output queue): a u-blox receiver answers a poll or a CFG within tens of ms
/// whatever the time within its epoch, which PX4's 250 ms ACK timeout relies on.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "hil/firmware_emu/sim_time.h"

namespace hil::link {

/// A run of bytes sent back to back: byte k starts at `t_first + k * byte_period`.
struct TimedChunk {
  Time t_first{};
  Duration byte_period{};
  std::string bytes;
  bool reply = false;  ///< placed ahead by UartTxQueue::SubmitAhead: later replies go behind it
  Time t_byte(std::size_t k) const { return t_first + byte_period * static_cast<std::int64_t>(k); }
  /// Time the last byte's stop bit ends.
  Time t_end() const { return t_first + byte_period * static_cast<std::int64_t>(bytes.size()); }
};

/// UART transmitter model; deterministic, no I/O.
class UartTxQueue {
 public:
  /// @param baud line rate in bit/s (> 0)
  /// @param buffer_bytes transmit buffer size; a message that would overflow it is dropped
  /// @param bits_per_byte start + data + parity + stop bits (10 for 8N1)
  UartTxQueue(int baud, std::size_t buffer_bytes, int bits_per_byte = 10);

  /// Queues a message ready at `t_ready`. Returns its timed bytes, or nothing if it was dropped.
  /// Calls must come in non-decreasing `t_ready` order.
  std::optional<TimedChunk> Submit(Time t_ready, std::string message);

  /// Where a reply went (SubmitAhead): before waiting[index] (index == waiting.size(): last).
  struct Placed {
    std::size_t index = 0;
    TimedChunk chunk;
  };
  /// Queues a reply ready at `t_ready` ahead of the queued messages that have not begun by then
  /// (but behind the replies queued before it: answers keep their order).
  /// `waiting` are the messages queued and not handed to the host yet, in line order; the first
  /// may be on the wire already. `line_free` is when the bytes before waiting[0] end. The
  /// messages behind the reply are moved later (their t_first changes) as far as it needs.
  /// Returns where the reply goes and its timed bytes, or nothing if it was dropped.
  std::optional<Placed> SubmitAhead(Time t_ready, std::string message, Time line_free,
                                    std::span<TimedChunk* const> waiting);

  /// Changes the baud for messages submitted from now on (the line drains at the old rate first).
  void set_baud(int baud);
  int baud() const { return baud_; }
  Duration byte_period() const { return byte_period_; }
  /// Bytes still waiting in the buffer at time t.
  std::size_t QueuedBytesAt(Time t) const;
  std::uint64_t messages_dropped() const { return messages_dropped_; }
  std::uint64_t bytes_dropped() const { return bytes_dropped_; }
  std::uint64_t bytes_sent() const { return bytes_sent_; }

 private:
  int baud_;
  int bits_per_byte_;
  std::size_t buffer_bytes_;
  Duration byte_period_{};
  /// Whether a message of `bytes` fits the buffer at `t_ready` (counts it as dropped if not).
  bool Admit(Time t_ready, std::size_t bytes);

  Time busy_until_{};
  std::uint64_t messages_dropped_ = 0, bytes_dropped_ = 0, bytes_sent_ = 0;
};

}  // namespace hil::link

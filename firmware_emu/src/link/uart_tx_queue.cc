#include "hil/firmware_emu/link/uart_tx_queue.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hil::link {

UartTxQueue::UartTxQueue(int baud, std::size_t buffer_bytes, int bits_per_byte)
    : baud_(baud), bits_per_byte_(bits_per_byte), buffer_bytes_(buffer_bytes) {
  set_baud(baud);
}

void UartTxQueue::set_baud(int baud) {
  if (baud <= 0)
    throw std::invalid_argument("UART baud must be positive, got " + std::to_string(baud));
  baud_ = baud;
  // 1e9 * bits / baud, rounded to the nanosecond
  byte_period_ = Duration{(1000000000LL * bits_per_byte_ + baud / 2) / baud};
}

std::size_t UartTxQueue::QueuedBytesAt(Time t) const {
  if (busy_until_ <= t) return 0;
  const auto remaining = (busy_until_ - t).count();
  return static_cast<std::size_t>((remaining + byte_period_.count() - 1) / byte_period_.count());
}

std::optional<TimedChunk> UartTxQueue::Submit(Time t_ready, std::string message) {
  if (QueuedBytesAt(t_ready) + message.size() > buffer_bytes_) {
    ++messages_dropped_;
    bytes_dropped_ += message.size();
    return std::nullopt;
  }
  TimedChunk chunk;
  chunk.t_first = std::max(t_ready, busy_until_);
  chunk.byte_period = byte_period_;
  chunk.bytes = std::move(message);
  busy_until_ = chunk.t_end();
  bytes_sent_ += chunk.bytes.size();
  return chunk;
}

}  // namespace hil::link

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

bool UartTxQueue::Admit(Time t_ready, std::size_t bytes) {
  if (QueuedBytesAt(t_ready) + bytes <= buffer_bytes_) return true;
  ++messages_dropped_;
  bytes_dropped_ += bytes;
  return false;
}

std::optional<TimedChunk> UartTxQueue::Submit(Time t_ready, std::string message) {
  if (!Admit(t_ready, message.size())) return std::nullopt;
  TimedChunk chunk;
  chunk.t_first = std::max(t_ready, busy_until_);
  chunk.byte_period = byte_period_;
  chunk.bytes = std::move(message);
  busy_until_ = chunk.t_end();
  bytes_sent_ += chunk.bytes.size();
  return chunk;
}

std::optional<UartTxQueue::Placed> UartTxQueue::SubmitAhead(Time t_ready, std::string message,
                                                            Time line_free,
                                                            std::span<TimedChunk* const> waiting) {
  // the first waiting message not begun when the reply is ready; before it, the line is busy
  // until the one before it ends
  std::size_t k = 0;
  while (k < waiting.size() && (waiting[k]->t_first <= t_ready || waiting[k]->reply)) ++k;
  if (k == waiting.size()) {
    auto chunk = Submit(t_ready, std::move(message));
    if (!chunk) return std::nullopt;
    chunk->reply = true;
    return Placed{k, std::move(*chunk)};
  }
  if (!Admit(t_ready, message.size())) return std::nullopt;
  Placed placed{k, {}};
  placed.chunk.t_first = std::max(t_ready, k == 0 ? line_free : waiting[k - 1]->t_end());
  placed.chunk.byte_period = byte_period_;
  placed.chunk.bytes = std::move(message);
  placed.chunk.reply = true;
  Time end = placed.chunk.t_end();
  for (std::size_t j = k; j < waiting.size(); ++j) {
    waiting[j]->t_first = std::max(waiting[j]->t_first, end);
    end = waiting[j]->t_end();
  }
  busy_until_ = std::max(busy_until_, end);
  bytes_sent_ += placed.chunk.bytes.size();
  return placed;
}

}  // namespace hil::link

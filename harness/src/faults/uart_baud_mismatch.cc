#include "hil/harness/faults/uart_baud_mismatch.h"

#include <cmath>
#include <stdexcept>

namespace hil::harness {
namespace {

// The transmitted line level in tx bit slot k (k < 0 and past the end: idle high).
class TxLine {
 public:
  explicit TxLine(std::string_view bytes) : bytes_(bytes) {}
  bool Level(std::int64_t k) const {
    if (k < 0 || k >= static_cast<std::int64_t>(bytes_.size()) * 10) return true;
    const auto byte = static_cast<unsigned char>(bytes_[static_cast<std::size_t>(k / 10)]);
    const auto bit = k % 10;
    if (bit == 0) return false;  // start
    if (bit == 9) return true;   // stop
    return ((byte >> (bit - 1)) & 1u) != 0;
  }
  std::int64_t slots() const { return static_cast<std::int64_t>(bytes_.size()) * 10; }

 private:
  std::string_view bytes_;
};

}  // namespace

BaudMismatchResult ReceiveAtWrongBaud(std::string_view sent, int tx_baud, int rx_baud) {
  if (tx_baud <= 0 || rx_baud <= 0)
    throw std::invalid_argument("ReceiveAtWrongBaud: bauds must be positive");
  BaudMismatchResult r;
  const TxLine line(sent);
  // times in units of one tx bit
  const double rx_bit = static_cast<double>(tx_baud) / static_cast<double>(rx_baud);
  const auto level_at = [&](double t) {
    return line.Level(static_cast<std::int64_t>(std::floor(t)));
  };
  double t = 0;  // the receiver looks for a falling edge at or after t
  for (;;) {
    // falling edges sit on slot boundaries k: slot k-1 high, slot k low
    std::int64_t k = static_cast<std::int64_t>(std::ceil(t));
    while (k < line.slots() && !(line.Level(k - 1) && !line.Level(k))) ++k;
    if (k >= line.slots()) break;
    const double edge = static_cast<double>(k);
    if (level_at(edge + 0.5 * rx_bit)) {  // the start bit is gone at its middle: noise, not a byte
      t = edge + 0.5 * rx_bit;
      continue;
    }
    unsigned value = 0;
    for (int i = 1; i <= 8; ++i) {
      if (level_at(edge + (i + 0.5) * rx_bit)) value |= 1u << (i - 1);
    }
    const double stop_t = edge + 9.5 * rx_bit;
    if (level_at(stop_t)) {
      r.received.push_back(static_cast<char>(value));
    } else {
      r.received.push_back('\0');
      ++r.framing_errors;
    }
    t = stop_t;
  }
  return r;
}

}  // namespace hil::harness

#pragma once
/// @file
/// What a host UART receives when the device transmits at another baud (8N1 both sides).
///
/// The transmitter's waveform is rebuilt bit by bit (idle high, start bit low, 8 data bits LSB
/// first, stop bit high, bytes back to back, idle after the last); the receiver does what a UART
/// does: waits for a falling edge, samples the middle of each of its own bit times (start + 8 data
/// + stop), and looks for the next falling edge after the stop-bit sample. A byte whose stop bit
/// samples low is a framing error and reaches the reader as 0x00, as Linux delivers it with the
/// default termios (neither IGNPAR nor PARMRK). Fully deterministic: same bytes and bauds, same
/// output; equal bauds give the input back.

#include <cstdint>
#include <string>
#include <string_view>

namespace hil::harness {

struct BaudMismatchResult {
  std::string received;  ///< the bytes the host reads
  std::uint64_t framing_errors = 0;
};

/// @param tx_baud the device's (wrong) line rate, @param rx_baud the host's; both > 0.
BaudMismatchResult ReceiveAtWrongBaud(std::string_view sent, int tx_baud, int rx_baud);

}  // namespace hil::harness

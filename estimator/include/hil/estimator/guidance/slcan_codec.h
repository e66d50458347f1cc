#pragma once
/// @file
/// The guidance controller's side of a serial SLCAN (Lawicel) CAN adapter
/// (vectors/slcan/README.md): the records a host sends to set the bit rate, open and close the
/// channel and transmit a frame, and a reader of what the adapter sends back (received frames,
/// CR acknowledgements, BEL refusals, `z`/`Z` transmit acknowledgements). Independent of the
/// adapter emulator in firmware_emu; the golden file vectors/slcan/slcan_golden.txt ties the two.
/// Fixed buffers, no allocation; never throws on input.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hil/estimator/guidance/isobus_guidance_codec.h"

namespace hil::estimator::guidance {

/// A record ready to write (CR-terminated).
struct SlcanRecord {
  std::array<char, 32> bytes{};
  std::size_t size = 0;
  std::string_view view() const { return {bytes.data(), size}; }
};

/// `Sn\r` for a bit rate of the standard table (10k … 1M); false for another bit rate.
bool FormatSlcanBitrate(int bitrate_bps, SlcanRecord& out);
/// `O\r` (open), `C\r` (close).
SlcanRecord FormatSlcanOpen();
SlcanRecord FormatSlcanClose();
/// `Tiiiiiiii L dd…\r`: a 29-bit data frame (up to 8 bytes).
SlcanRecord FormatSlcanExtendedFrame(const IsobusFrame& frame);

/// What one record from the adapter was.
enum class SlcanReply : std::uint8_t {
  kNone,         ///< no complete record yet
  kAck,          ///< CR alone: a command succeeded
  kRefused,      ///< BEL: a command was refused
  kTransmitted,  ///< `z` / `Z`: a frame was sent
  kFrame,        ///< a received 29-bit data frame (`frame()` holds it)
  kOtherFrame,   ///< a received 11-bit or remote frame (not ISOBUS): ignored
  kMalformed,    ///< a record that is none of the above
};

/// Reads the adapter's byte stream one byte at a time. A received frame may carry the adapter's
/// 4-digit time stamp (`Z1`), which is skipped.
class SlcanReader {
 public:
  SlcanReply Feed(char byte);
  const IsobusFrame& frame() const { return frame_; }
  std::uint64_t malformed() const { return malformed_; }

 private:
  SlcanReply Finish();
  std::array<char, 40> buf_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
  IsobusFrame frame_;
  std::uint64_t malformed_ = 0;
};

}  // namespace hil::estimator::guidance

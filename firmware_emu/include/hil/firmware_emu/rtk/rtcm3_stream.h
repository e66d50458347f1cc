#pragma once
/// @file
/// The receiving side of the RTCM 3 transport layer (rtcm3_frame.h): an incremental parser that
/// takes a serial line's bytes one at a time, as a rover's UART delivers them, and returns each
/// frame as it completes: its body and whether its CRC-24Q matched. A frame whose CRC fails is
/// returned with `crc_failed` (its message number read from the corrupt body, as a receiver's
/// RXM-RTCM reports it) and the search for the next preamble resumes at the byte after the failed
/// one's preamble. Bytes outside frames are counted.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hil::rtcm3 {

/// One frame the parser completed.
struct ReceivedFrame {
  std::string body;
  bool crc_failed = false;
  int message_number() const;  ///< DF002; 0 for a body under 2 bytes
  int station_id() const;      ///< DF003 (the 12 bits after DF002); 0 for a short body
};

class StreamParser {
 public:
  /// Feeds one byte; appends the frames it completes to `out` (after a CRC failure, the failed
  /// frame and any frame found again among its bytes).
  void Feed(char byte, std::vector<ReceivedFrame>& out);
  std::uint64_t skipped_bytes() const { return skipped_; }

 private:
  void Complete(std::vector<ReceivedFrame>& out);
  std::string buf_;  // from the preamble on
  std::size_t need_ = 0;
  std::uint64_t skipped_ = 0;
};

}  // namespace hil::rtcm3

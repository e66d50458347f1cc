#pragma once
/// @file
/// NMEA 2000 on the receiving side: the PGN of a 29-bit identifier, and the reassembly of
/// fast-packet messages (ISO 11783-3 / NMEA 2000 "fast packet": frame 0 = sequence counter in bits
/// 5–7, frame index 0 in bits 0–4, the total payload length, 6 payload bytes; frames 1…31 = the
/// same counter, their index, 7 payload bytes). Messages are reassembled per (source address, PGN);
/// a frame out of turn (wrong counter or index) drops the message under way and is counted. No
/// reliance on frame order between different sources or PGNs.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace hil::harness {

/// PGN of a 29-bit identifier (PDU1: destination cleared; PDU2: group extension kept).
std::uint32_t N2kPgnFromId(std::uint32_t id29);
/// Source address of a 29-bit identifier.
inline std::uint8_t N2kSourceFromId(std::uint32_t id29) {
  return static_cast<std::uint8_t>(id29 & 0xFF);
}

struct N2kFastPacketStats {
  std::uint64_t frames = 0, messages = 0;
  std::uint64_t out_of_turn = 0;  ///< a frame that does not continue the message under way
  std::uint64_t bad_frames = 0;   ///< empty frame, first frame without a length, length > 223
  std::uint64_t abandoned = 0;    ///< a new first frame while a message was still incomplete
};

class N2kFastPacketAssembler {
 public:
  /// The longest fast-packet payload: 6 + 31 × 7 bytes.
  static constexpr std::size_t kMaxPayload = 223;
  /// Feeds one frame of a fast-packet PGN; returns the payload (exactly the announced length) when
  /// this frame completes a message.
  std::optional<std::string> Add(std::uint8_t source, std::uint32_t pgn, std::string_view data);
  const N2kFastPacketStats& stats() const { return stats_; }

 private:
  struct Partial {
    int sequence = -1;
    int next_index = 0;
    std::size_t expected = 0;
    std::string bytes;
  };
  std::map<std::uint64_t, Partial> partial_;
  N2kFastPacketStats stats_;
};

}  // namespace hil::harness

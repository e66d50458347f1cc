#pragma once
/// @file
/// Benewake TF-Luna / TFmini-S UART framing (seeds_001_003.md §C.3.1): the 9-byte data frame
/// `59 59 b2 … b7 CS` and the command / reply frame `5A LEN ID payload CS`, LEN = the whole
/// frame's length; CS = low 8 bits of the sum of the bytes before it. The field meaning of the
/// payloads is in benewake_codec.h; this layer only frames and checks.

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace hil::rangefinder {

inline constexpr std::size_t kDataFrameSize = 9;
inline constexpr unsigned char kDataHeader = 0x59, kCommandHeader = 0x5A;
/// Shortest and longest command frames this framer accepts (header, LEN, ID, CS; longest: the
/// 8-byte baud-rate command with room for vendor extensions).
inline constexpr std::size_t kMinCommandSize = 4, kMaxCommandSize = 32;

/// Low 8 bits of the sum of `bytes`.
std::uint8_t Sum8(std::string_view bytes);
/// `59 59` + the six payload bytes + CS.
std::string FrameData(const std::array<std::uint8_t, 6>& payload);
/// `5A LEN ID payload CS` with LEN = payload size + 4.
std::string FrameCommand(std::uint8_t id, std::string_view payload);

/// One command (host → module) or reply (module → host) frame.
struct CommandFrame {
  std::uint8_t id = 0;
  std::string payload;
  bool checksum_zero =
      false;  ///< CS was 00 instead of the sum (accepted: checksums are off by default)
};

struct CommandReaderStats {
  std::uint64_t frames = 0, zero_checksum = 0, bad_checksum = 0, garbage_bytes = 0;
};

/// Extracts command frames from a byte stream that may arrive in any pieces. A byte that cannot
/// start a frame, or a LEN outside [kMinCommandSize, kMaxCommandSize], is garbage; a frame whose CS
/// is neither the sum nor 00 is counted and the search resumes one byte after its header.
class CommandReader {
 public:
  using Handler = std::function<void(const CommandFrame&)>;
  explicit CommandReader(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const CommandReaderStats& stats() const { return stats_; }

 private:
  Handler handler_;
  std::string buf_;
  CommandReaderStats stats_;
};

}  // namespace hil::rangefinder

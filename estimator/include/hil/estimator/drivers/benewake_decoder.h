#pragma once
/// @file
/// Tolerant decoder of a Benewake TF-Luna / TFmini-S UART stream (seeds_001_003.md §C.3.1): 9-byte
/// data frames `59 59 DistL DistH AmpL AmpH TempL TempH CS` and 5A reply frames
/// `5A LEN ID payload CS` (CS = low 8 bits of the sum of the preceding bytes). Bytes may arrive in
/// any pieces; a byte that cannot start a frame is garbage; a bad checksum is counted and the
/// search resumes one byte after the header. Validity follows the module's manual: TF-Luna Dist 0
/// or Amp < 100 or Amp 65535; TFmini-S Dist ≥ 0xFFFC (−1, −2, −4). Never throws on input; fixed
/// buffer, no allocation. Independent of the emulator (firmware_emu/src/rangefinder), tied to it
/// by vectors/rangefinder.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

namespace hil::estimator::drivers {

enum class BenewakeUnit { kCm, kMm };
enum class BenewakeModel { kTfLuna, kTfminiS };

struct BenewakeRange {
  std::uint16_t dist_raw = 0, amp = 0, temp_raw = 0;
  double distance_m = 0;     ///< 0 when invalid
  double temperature_c = 0;  ///< raw / 8 − 256
  bool valid = false;
};

struct BenewakeReply {
  std::uint8_t id = 0;
  std::array<std::uint8_t, 28> payload{};
  std::size_t payload_size = 0;
};

struct BenewakeDecoderStats {
  std::uint64_t ranges = 0, invalid_ranges = 0, replies = 0, bad_checksum = 0, garbage_bytes = 0;
};

class BenewakeDecoder {
 public:
  using RangeHandler = std::function<void(const BenewakeRange&)>;
  using ReplyHandler = std::function<void(const BenewakeReply&)>;
  BenewakeDecoder(BenewakeModel model, RangeHandler on_range, ReplyHandler on_reply = {})
      : model_(model), on_range_(std::move(on_range)), on_reply_(std::move(on_reply)) {}
  void Feed(std::string_view bytes);
  /// The distance unit of data frames (cm after power-up; mm after output format 0x06). A reply
  /// to an output-format command switches it by itself.
  void set_unit(BenewakeUnit unit) { unit_ = unit; }
  BenewakeUnit unit() const { return unit_; }
  const BenewakeDecoderStats& stats() const { return stats_; }
  /// The bytes fed so far.
  std::uint64_t stream_bytes() const { return stream_bytes_; }
  /// Inside a handler: the stream offset just past the frame's last byte (a module sends a frame
  /// per period, so its place in the stream is its time).
  std::uint64_t frame_end_bytes() const { return frame_end_bytes_; }

 private:
  /// Bytes of a complete frame at the buffer's start, 0 when more are needed, −1 for garbage.
  int FrameLength() const;
  void Emit(std::size_t len);
  static constexpr std::size_t kMax = 32;
  BenewakeModel model_;
  RangeHandler on_range_;
  ReplyHandler on_reply_;
  BenewakeUnit unit_ = BenewakeUnit::kCm;
  BenewakeDecoderStats stats_;
  std::array<unsigned char, 2 * kMax> buf_{};
  std::size_t len_ = 0;
  std::uint64_t stream_bytes_ = 0, frame_end_bytes_ = 0;
};

}  // namespace hil::estimator::drivers

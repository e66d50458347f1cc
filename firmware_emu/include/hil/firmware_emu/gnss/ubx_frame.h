#pragma once
/// @file
/// UBX framing (u-blox binary protocol): `B5 62 class id len(U2 LE) payload CK_A CK_B`, the 8-bit
/// Fletcher checksum over class, id, length and payload. Little-endian field writers and readers
/// that assemble payloads byte by byte (no struct punning), the framing of a buffer read whole
/// (logs, captures), and an incremental parser for the host → receiver direction that splits a
/// byte stream into UBX frames and NMEA sentences.
/// Facts: shared/reference/ublox5.md §1.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hil::gnss::ubx {

inline constexpr std::uint8_t kSync1 = 0xB5;
inline constexpr std::uint8_t kSync2 = 0x62;
/// Longest payload the parser accepts from the host (a decoder's cap, not the protocol's).
inline constexpr std::size_t kMaxInputPayload = 4096;

/// Message classes of a u-blox 5.
enum Class : std::uint8_t {
  kNav = 0x01,
  kRxm = 0x02,
  kInf = 0x04,
  kAck = 0x05,
  kCfg = 0x06,
  kMon = 0x0A,
  kAid = 0x0B,
  kTim = 0x0D,
  kNmeaStd = 0xF0,
  kNmeaPubx = 0xF1
};

/// Appends little-endian fields to a payload.
class Writer {
 public:
  Writer& U1(std::uint64_t v);
  Writer& U2(std::uint64_t v);
  Writer& U4(std::uint64_t v);
  Writer& I1(std::int64_t v);
  Writer& I2(std::int64_t v);
  Writer& I4(std::int64_t v);
  /// IEEE 754 single (R4) and double (R8), little-endian.
  Writer& R4(float v);
  Writer& R8(double v);
  /// Fixed-width character field, NUL padded (and truncated to `width`).
  Writer& Chars(std::string_view text, std::size_t width);
  Writer& Zeros(std::size_t n);
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  std::vector<std::uint8_t> bytes_;
};

/// Reads little-endian fields of a payload at byte offsets. Out-of-range reads return 0.
class Reader {
 public:
  explicit Reader(const std::vector<std::uint8_t>& payload) : p_(payload) {}
  std::uint8_t U1(std::size_t off) const;
  std::uint16_t U2(std::size_t off) const;
  std::uint32_t U4(std::size_t off) const;
  std::int8_t I1(std::size_t off) const;
  std::int16_t I2(std::size_t off) const;
  std::int32_t I4(std::size_t off) const;
  std::size_t size() const { return p_.size(); }

 private:
  const std::vector<std::uint8_t>& p_;
};

/// Fletcher-8 checksum pair {CK_A, CK_B} over `bytes` (class, id, length, payload).
std::pair<std::uint8_t, std::uint8_t> Checksum(std::string_view bytes);
/// A complete frame as a byte string.
std::string Frame(std::uint8_t cls, std::uint8_t id, const std::vector<std::uint8_t>& payload);
inline std::string Frame(std::uint8_t cls, std::uint8_t id, const Writer& w) {
  return Frame(cls, id, w.bytes());
}

/// What a byte buffer holds at a sync pair: the framing of a log or capture read whole (hil
/// validate, dataset import), where the host's incremental InputParser reads a stream byte by byte.
enum class FrameAtStatus : std::uint8_t {
  kFrame,        ///< a whole frame with a valid checksum
  kHeaderCut,    ///< fewer than the 6 bytes of sync pair, class, id and length
  kTooLong,      ///< a length field over the caller's limit
  kCut,          ///< the frame runs past the end of the bytes
  kBadChecksum,  ///< whole, but CK_A CK_B do not match
};
struct FrameAt {
  FrameAtStatus status = FrameAtStatus::kHeaderCut;
  std::uint8_t cls = 0, id = 0;    ///< from the header (all but kHeaderCut)
  std::size_t payload_length = 0;  ///< from the header (all but kHeaderCut)
  std::string_view payload;        ///< kFrame: a view into the bytes parsed
  std::size_t frame_size() const { return 8 + payload_length; }
};
/// The frame at the start of `bytes`, which begin with the sync pair B5 62. Checked in this order:
/// header, length against `max_payload`, end of the bytes, checksum.
FrameAt ParseFrameAt(std::string_view bytes, std::size_t max_payload = 0xFFFF);

/// One unit of host input: a checksum-valid UBX frame or a checksum-valid NMEA sentence.
struct InputMessage {
  enum class Kind { kUbx, kNmea } kind = Kind::kUbx;
  std::uint8_t cls = 0, id = 0;
  std::vector<std::uint8_t> payload;  ///< UBX payload
  std::string sentence;               ///< NMEA: the body between `$` and `*`
};

/// Incremental splitter of host bytes into UBX frames and NMEA sentences. Bytes that belong to
/// neither, frames with a bad checksum and oversize frames are discarded (counted).
class InputParser {
 public:
  /// Feeds bytes; returns the complete messages they finished.
  std::vector<InputMessage> Feed(std::string_view bytes);
  std::uint64_t discarded_frames() const { return discarded_; }

 private:
  void FeedByte(std::uint8_t b, std::vector<InputMessage>& out);
  enum class State { kIdle, kSecondSync, kHeader, kPayload, kNmea } state_ = State::kIdle;
  std::string buf_;
  std::size_t need_ = 0;
  std::uint64_t discarded_ = 0;
};

}  // namespace hil::gnss::ubx

#pragma once
/// @file
/// Tolerant UBX decoder for the u-blox 5 messages navd uses, and the epoch assembler that joins
/// them into GnssSamples. Framing: B5 62, class, id, u16 length, payload, Fletcher-8 checksum over
/// class..payload. Bytes may come in any pieces, mixed with NMEA or garbage; bad checksums and
/// overlong lengths are counted and the search restarts one byte after the B5. Never throws.
/// Messages: NAV-POSLLH (01 02), NAV-SOL (01 06), NAV-VELNED (01 12), NAV-TIMEGPS (01 20),
/// NAV-TIMEUTC (01 21), ACK-ACK (05 01), ACK-NAK (05 00).

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

/// One decoded UBX message (fields of its kind filled).
struct UbxMessage {
  std::uint8_t cls = 0, id = 0;
  std::uint32_t itow_ms = 0;
  // NAV-POSLLH
  double lat_deg = 0, lon_deg = 0, height_m = 0, h_msl_m = 0, h_acc_m = 0, v_acc_m = 0;
  // NAV-VELNED
  double vel_n_mps = 0, vel_e_mps = 0, vel_d_mps = 0, s_acc_mps = 0;
  // NAV-SOL / NAV-TIMEGPS
  int week = -1, gps_fix = 0, num_sv = 0, leap_s = 0;
  std::uint8_t flags = 0;  ///< SOL flags (b0 gpsFixOk) or TIMEGPS valid bits
  std::int32_t ftow_ns = 0;
  // ACK
  std::uint8_t ack_cls = 0, ack_id = 0;
};

struct UbxDecoderStats {
  std::uint64_t frames_ok = 0, bad_checksum = 0, overlong = 0, unsupported = 0, garbage_bytes = 0,
                acks = 0, naks = 0;
};

class UbxDecoder {
 public:
  using Handler = std::function<void(const UbxMessage&)>;
  explicit UbxDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const UbxDecoderStats& stats() const { return stats_; }
  /// Builds a frame (sync, header, payload, checksum), e.g. for CFG commands.
  static std::size_t Encode(std::uint8_t cls, std::uint8_t id, std::string_view payload, char* out,
                            std::size_t cap);

 private:
  void Scan();
  void Dispatch(const char* frame, std::size_t len);
  static constexpr std::size_t kMaxPayload = 1024;
  Handler handler_;
  UbxDecoderStats stats_;
  std::array<char, kMaxPayload + 8> buf_{};
  std::size_t len_ = 0;
};

/// Joins POSLLH, VELNED and SOL of one epoch (same iTOW, any order) into a GnssSample on GPS time.
/// The epoch is emitted when all three are present, or, with what it has, when a later epoch
/// starts.
class UbxEpochAssembler {
 public:
  std::optional<GnssSample> Add(const UbxMessage& m);
  int leap_seconds() const { return leap_s_; }

 private:
  std::optional<GnssSample> Flush();
  std::uint32_t itow_ = 0;
  bool have_pos_ = false, have_vel_ = false, have_sol_ = false;
  UbxMessage pos_, vel_, sol_;
  int week_ = -1, leap_s_ = 18;
};

}  // namespace hil::estimator::drivers

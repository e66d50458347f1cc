#pragma once
/// @file
/// Tolerant UBX decoder for the u-blox 5 messages navd uses, and the epoch assembler that joins
/// them into GnssSamples. Framing: B5 62, class, id, u16 length, payload, Fletcher-8 checksum over
/// class..payload. Bytes may come in any pieces, mixed with NMEA or garbage; bad checksums and
/// overlong lengths are counted and the search restarts one byte after the B5. Never throws.
/// Messages: NAV-POSLLH (01 02), NAV-DOP (01 04), NAV-SOL (01 06), NAV-VELNED (01 12),
/// NAV-TIMEGPS (01 20), NAV-TIMEUTC (01 21), ACK-ACK (05 01), ACK-NAK (05 00); and the u-blox 8/9
/// (protocol 27+) NAV-PVT (01 07, 92 bytes). Valid frames of other messages are counted as
/// `unsupported`, never as garbage. With an other-bytes sink (SetOtherBytesSink) the decoder is the
/// framer of a mixed UBX + NMEA stream: the bytes outside valid UBX frames go, in order, to the
/// sink (e.g. an NmeaDecoder) instead of being counted as garbage here.

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
  // NAV-SOL: the solution in ECEF (E), its 3-D accuracies
  std::array<double, 3> p_E_m{}, v_E_mps{};
  double p_acc_m = 0, sol_s_acc_mps = 0;
  // NAV-DOP (and NAV-SOL pDOP)
  double pdop = 0, hdop = 0, vdop = 0;
  // ACK
  std::uint8_t ack_cls = 0, ack_id = 0;
  // NAV-PVT (also sets itow_ms, gps_fix = fixType, flags, num_sv, lat/lon/height/h_msl, h_acc_m,
  // v_acc_m, vel_*_mps, s_acc_mps, pdop)
  std::uint8_t utc_valid = 0;  ///< valid: b0 validDate, b1 validTime, b2 fullyResolved
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  std::int32_t utc_nano_ns = 0;  ///< nano: fraction of the UTC second, −5e8 … 1e9
  double g_speed_mps = 0, head_mot_deg = 0;
  std::uint16_t flags3 = 0;  ///< b0 invalidLlh, b1–4 lastCorrectionAge
};

/// NAV-PVT flags: gnssFixOK (b0), diffSoln (b1), carrSoln (b6–7: 0 none, 1 float, 2 fixed).
inline bool PvtGnssFixOk(const UbxMessage& m) { return (m.flags & 0x01) != 0; }
inline bool PvtDiffSoln(const UbxMessage& m) { return (m.flags & 0x02) != 0; }
inline int PvtCarrSoln(const UbxMessage& m) { return (m.flags >> 6) & 0x03; }

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
  /// Bytes outside valid UBX frames go here, in stream order, instead of counting as garbage.
  void SetOtherBytesSink(std::function<void(std::string_view)> sink) { other_ = std::move(sink); }
  /// Builds a frame (sync, header, payload, checksum), e.g. for CFG commands.
  static std::size_t Encode(std::uint8_t cls, std::uint8_t id, std::string_view payload, char* out,
                            std::size_t cap);

 private:
  void Scan();
  void Dispatch(const char* frame, std::size_t len);
  // Drops the buffer's first n bytes: to the sink if any, else counted as garbage if `garbage`
  // (the sync byte of a frame that failed its checksum or length is counted there instead).
  void Skip(std::size_t n, bool garbage = true);
  static constexpr std::size_t kMaxPayload = 1024;
  Handler handler_;
  std::function<void(std::string_view)> other_;
  UbxDecoderStats stats_;
  std::array<char, kMaxPayload + 8> buf_{};
  std::size_t len_ = 0;
};

/// Joins the navigation messages of one epoch (same iTOW, any order) into a GnssSample on GPS
/// time, from whichever of them the receiver sends: position from NAV-POSLLH, else from NAV-SOL's
/// ECEF position (the estimator's geodesy); velocity from NAV-VELNED, else from NAV-SOL's ECEF
/// velocity rotated into ENU at that position; fix type, gpsFixOk, week and numSV from NAV-SOL.
/// A fix is reported when NAV-SOL (if sent) says gpsFixOk with a 2-D or 3-D fix.
/// The epoch is emitted as soon as it holds POSLLH, VELNED and SOL, or every message this
/// receiver has been seen to send per epoch (learned from the epochs before); otherwise, with
/// what it has, when a later epoch starts.
/// The epochs one message ends: none, one, or two (the previous epoch, flushed by this message's
/// new iTOW, and the new epoch when this message alone completes it). Iterable.
struct UbxEpochs {
  std::array<GnssSample, 2> samples;
  std::size_t count = 0;
  const GnssSample* begin() const { return samples.data(); }
  const GnssSample* end() const { return samples.data() + count; }
  bool empty() const { return count == 0; }
};

class UbxEpochAssembler {
 public:
  UbxEpochs Add(const UbxMessage& m);
  int leap_seconds() const { return leap_s_; }
  /// GPS − UTC for the solutions' UTC times: the receiver's own value once a NAV-TIMEGPS said it
  /// is valid (leapS valid flag), else `configured` (navd's [time] leap_seconds).
  int UtcLeapSeconds(int configured) const { return leap_reported_ ? leap_s_ : configured; }
  /// Vertical 1σ given for a 2-D fix, whose height the receiver holds instead of measuring.
  static constexpr double kHeldHeightStd_m = 1000.0;

 private:
  enum : std::uint8_t { kPos = 1, kVel = 2, kSol = 4 };
  std::optional<GnssSample> Flush();
  bool Complete() const;
  void FillPosition(GnssSample& g) const;
  void FillVelocity(GnssSample& g) const;
  std::uint32_t itow_ = 0;
  std::uint8_t have_ = 0;      // messages of the current epoch
  std::uint8_t expected_ = 0;  // messages this receiver sends per epoch (0: not yet known)
  UbxMessage pos_, vel_, sol_;
  int week_ = -1, leap_s_ = 18;
  bool leap_reported_ = false;  // leap_s_ came from the receiver
};

}  // namespace hil::estimator::drivers

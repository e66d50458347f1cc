#pragma once
/// @file
/// `hil validate`: conformance of a device's byte stream (a capture file, a gpsd-style log, a live
/// serial device) or of a CAN log against a protocol profile. The validator is a judge with its own
/// framers, independent of the emulator's encoders and navd's decoders.
///
/// Protocols:
///  - nmea:  NMEA 0183 framing (`$…*HH`, ≤ 82 characters), checksums, known sentence layouts
///           (field counts and formats), epoch grouping by time of day, epoch rate and gaps;
///  - ubx:   UBX framing (sync, little-endian length, Fletcher checksum), known class/id and the
///           payload lengths of fixed-size messages, iTOW epochs (monotonic, gaps), message rates;
///  - neo5m: both, against the u-blox 5 (NEO-5M) profile: GP talker, the default NMEA epoch
///           RMC, VTG, GGA, GSA, GSV…, GLL in that order, only messages a u-blox 5 has, epoch
///           rate ≤ 4 Hz, bytes per epoch within the line time at the baud (a capture's own,
///           else --baud), epoch timing;
///  - mcu:   the MCU frame protocol v1 (ValidateMcuStream);
///  - can:   `candump -l` log lines (format, identifiers, lengths), monotonic timestamps, per-ID
///           rates and NMEA 2000 fast-packet sequence continuity.
/// Every serial protocol, on a capture: no byte closer to the one before it than the recorded line
/// rate allows (CheckLineRate).
/// Errors make a stream non-conforming; warnings (gaps at capture boundaries, a partial epoch) are
/// reported but do not.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hil::harness {

enum class ValidateProtocol { kNmea, kUbx, kNeo5m, kCan };

/// Bytes to validate, with per-byte emulated or arrival times when the source has them.
struct ByteStream {
  std::string bytes;
  std::vector<std::int64_t> t_ns;  ///< empty, or one time per byte
  std::string
      description;  ///< e.g. "hil capture v2 (link ttyGPS, serial, 9600 baud), device bytes"
  /// The line rate the source records (a hil capture's `# link NAME serial BAUD` header), its
  /// t_ns then being each byte's start on the line; 0 when it records none (a raw log, a live
  /// device: arrival times, several bytes to a read).
  int line_baud = 0;
};

/// Reads SOURCE: a hil capture file (`# hil capture v1`, its tx bytes with their times and the
/// baud of its header), a serial device or pty (listened to for `listen_s` at `baud`), or any
/// other file as raw bytes (a gpsd-style log: its leading `#` comment lines are dropped).
/// @throws std::runtime_error naming the source when it cannot be read.
ByteStream ReadByteSource(const std::string& source, double listen_s, int baud);

/// The line rate to judge a stream at: the rate its source records (ByteStream::line_baud) or,
/// when it records none, `baud` (`hil validate --baud`, default 9600).
/// @throws std::invalid_argument when `baud_given` and `baud` is not the recorded rate.
int ValidationBaud(const ByteStream& stream, int baud, bool baud_given);

/// The character time of an 8N1 line (10 bits: start, 8 data, stop; the emulated UARTs' framing).
constexpr double LineCharacterNs(int baud) { return 1e10 / baud; }
/// A byte may start this fraction of a character time early and still have crossed the line: the
/// usual UART baud-rate tolerance (±2 %; our choice, not a capture's). Captures round the byte
/// period to whole nanoseconds, far inside it.
constexpr double kLineRateTolerance = 0.02;

struct ValidationFinding {
  bool error = true;  ///< false: a warning
  std::string check;  ///< e.g. "checksum", "epoch_order"
  std::string message;
  std::int64_t offset = -1;  ///< byte offset (or line number for CAN logs), -1 when not applicable
};

struct MessageStats {
  std::size_t count = 0;
  double rate_hz = 0;  ///< count per second over the stream's epoch span (0 when unknown)
};

struct ValidationReport {
  std::string protocol, source, description;
  std::size_t bytes = 0, frames = 0, bad_frames = 0, garbage_bytes = 0, epochs = 0;
  std::optional<double> epoch_rate_hz, epoch_first_byte_offset_p50_ms, epoch_first_byte_jitter_ms;
  std::map<std::string, MessageStats> messages;
  std::vector<ValidationFinding> findings;
  std::size_t errors() const;
  bool conforms() const { return errors() == 0 && frames > 0; }
};

/// Bytes that could not have crossed the line: with a recorded line rate and the bytes' line times
/// (a capture), every byte that starts less than (1 − kLineRateTolerance) character times after
/// the one before it. One error `line_rate` (how many, the first, the shortest spacing); nothing
/// when the stream records no line rate. ValidateStream and ValidateMcuStream make this check.
void CheckLineRate(const ByteStream& stream, ValidationReport& report);

/// Validates a byte stream. `baud` bounds the bytes per epoch for neo5m (0: not checked).
ValidationReport ValidateStream(ValidateProtocol protocol, const ByteStream& stream, int baud);

/// Validates an MCU frame protocol v1 stream (vectors/mcu/mcu_frame_protocol.md): framing, CRC,
/// sequence gaps (resets allowed), per-type tick monotonicity, IMU rate against STATUS, time
/// pulses.
ValidationReport ValidateMcuStream(const ByteStream& stream);

/// Validates a candump -l log file's text.
ValidationReport ValidateCanLog(const std::string& text);

/// Writes the report as JSON. @throws std::runtime_error naming the file.
void WriteValidationJson(const ValidationReport& report, const std::string& path);
/// A human-readable summary (at most `max_findings` findings listed).
std::string ValidationSummary(const ValidationReport& report, std::size_t max_findings = 20);

}  // namespace hil::harness

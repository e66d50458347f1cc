#pragma once
/// @file
/// Tolerant NMEA 0183 decoder for navd: accepts bytes in arbitrary pieces (split reads), skips
/// garbage and binary frames between sentences, verifies checksums (bad ones are counted and
/// dropped), and decodes the sentences navd uses (GGA, RMC, GSA) into value types. Never throws on
/// input.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace hil::estimator::drivers {

/// One decoded GGA, RMC or GSA sentence. Missing fields stay empty (std::nullopt).
struct NmeaFix {
  enum class Kind : std::uint8_t { kGga, kRmc, kGsa } kind = Kind::kGga;
  std::optional<std::int64_t> utc_time_of_day_ns;  ///< hhmmss.ss as nanoseconds since midnight
  std::optional<int> day, month, year;             ///< RMC date (year with century)
  bool valid = false;                              ///< GGA quality > 0, or RMC status 'A'
  int quality = 0;  ///< GGA fix quality (0 invalid, 1 GPS, 2 DGPS, 4 RTK…)
  std::optional<double> lat_deg, lon_deg;
  std::optional<double> msl_altitude_m, geoid_separation_m;
  /// The step of the altitude as written (10^−decimals: 0.1 m for "141.1"), 0 when absent.
  double altitude_step_m = 0.0;
  /// The step of the geoid separation as written (0.1 m for "11.7"), 0 when absent.
  double geoid_step_m = 0.0;
  std::optional<double> hdop;
  /// GSA: the solution's VDOP (and HDOP above), when its fix type is 3-D and the VDOP is not
  /// the 99.99 of "no solution"; GSA carries no position or time (valid stays false)
  std::optional<double> vdop;
  int num_sv = 0;
  std::optional<double> speed_mps, course_deg;  ///< RMC
};

/// Counters a host can report as health.
struct NmeaDecoderStats {
  std::uint64_t sentences_ok = 0;
  std::uint64_t bad_checksum = 0;
  std::uint64_t malformed = 0;      ///< checksum fine, fields unusable
  std::uint64_t unsupported = 0;    ///< valid sentence of a type navd does not use
  std::uint64_t overlong = 0;       ///< longer than the 82-character limit plus slack
  std::uint64_t garbage_bytes = 0;  ///< bytes outside any sentence
};

/// Incremental decoder; feed it bytes, it calls the handler for each decoded sentence.
class NmeaDecoder {
 public:
  using Handler = std::function<void(const NmeaFix&)>;
  explicit NmeaDecoder(Handler handler) : handler_(std::move(handler)) {}

  /// Consumes a piece of the byte stream.
  void Feed(std::string_view bytes);
  const NmeaDecoderStats& stats() const { return stats_; }

  /// Parses one complete sentence "$...*HH" (CR/LF optional); nullopt when invalid or unused.
  static std::optional<NmeaFix> ParseSentence(std::string_view sentence, NmeaDecoderStats* stats);

 private:
  static constexpr std::size_t kMaxSentence = 120;
  Handler handler_;
  NmeaDecoderStats stats_;
  std::string line_;
  bool in_sentence_ = false;
};

}  // namespace hil::estimator::drivers

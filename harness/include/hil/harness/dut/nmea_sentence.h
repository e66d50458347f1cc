#pragma once
/// @file
/// The harness's own reading of NMEA 0183 sentences (the judge: independent of the emulator's
/// encoder and navd's decoder). `$TTSSS,f1,f2,…*HH` with HH the XOR of the bytes between `$` and
/// `*` in two hex digits; the line end (CR LF or LF) is not part of the sentence.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hil::harness {

struct NmeaSentence {
  std::string address;              ///< e.g. "GPGGA", "PUBX"
  std::vector<std::string> fields;  ///< the fields after the address
  std::string talker() const { return address.size() == 5 ? address.substr(0, 2) : ""; }
  std::string type() const { return address.size() == 5 ? address.substr(2) : address; }
};

/// Parse result: the sentence, or why it is not one.
struct NmeaParse {
  std::optional<NmeaSentence> sentence;
  std::string error;  ///< empty when valid
};

/// Parses one line (trailing CR/LF ignored). A missing or wrong checksum is an error.
NmeaParse ParseNmeaSentence(std::string_view line);

/// ddmm.mmmm + hemisphere to signed degrees; nullopt when empty or malformed.
std::optional<double> NmeaDegrees(const std::string& value, const std::string& hemisphere);
/// hhmmss[.ss] to seconds of day; nullopt when malformed.
std::optional<double> NmeaTimeOfDay(const std::string& value);

}  // namespace hil::harness

#pragma once
// NMEA 0183 sentences as fields: checksum verified, split at commas. Standard library only.
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hil_example {

/// The fields of "$TTXXX,a,b*hh" (the address first) when the checksum holds.
inline std::optional<std::vector<std::string>> NmeaFields(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  const std::size_t star = line.rfind('*');
  if (line.empty() || line[0] != '$' || star == std::string_view::npos || star + 3 > line.size())
    return std::nullopt;
  unsigned x = 0;
  for (std::size_t i = 1; i < star; ++i) x ^= static_cast<unsigned char>(line[i]);
  char* end = nullptr;
  const std::string hex(line.substr(star + 1, 2));
  if (std::strtoul(hex.c_str(), &end, 16) != x || *end != '\0') return std::nullopt;
  std::vector<std::string> f;
  std::size_t start = 1;
  for (std::size_t i = 1; i <= star; ++i) {
    if (i == star || line[i] == ',') {
      f.emplace_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  return f;
}

/// The sentence type of an address ("GPGGA" → "GGA").
inline std::string_view SentenceType(const std::string& address) {
  return address.size() >= 5 ? std::string_view(address).substr(2) : std::string_view();
}

/// ddmm.mmmm (width 2) or dddmm.mmmm (width 3) and a hemisphere to signed degrees.
inline double NmeaDegrees(const std::string& value, const std::string& hemisphere, int width) {
  const double d =
      std::atof(value.substr(0, width).c_str()) + std::atof(value.substr(width).c_str()) / 60.0;
  return hemisphere == "S" || hemisphere == "W" ? -d : d;
}

/// hhmmss.ss to seconds of the day.
inline double SecondsOfDay(const std::string& hhmmss) {
  if (hhmmss.size() < 6) return 0.0;
  return std::atoi(hhmmss.substr(0, 2).c_str()) * 3600.0 +
         std::atoi(hhmmss.substr(2, 2).c_str()) * 60.0 + std::atof(hhmmss.substr(4).c_str());
}

/// A GGA with a fix: quality not 0 and a position.
inline bool GgaHasFix(const std::vector<std::string>& f) {
  return f.size() >= 12 && !f[6].empty() && f[6] != "0" && !f[2].empty() && !f[4].empty();
}

/// GGA's ellipsoidal height: MSL altitude plus the geoid separation.
inline double GgaEllipsoidalHeight(const std::vector<std::string>& f) {
  return std::atof(f[9].c_str()) + std::atof(f[11].c_str());
}

}  // namespace hil_example

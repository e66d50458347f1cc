#include "hil/firmware_emu/gnss/nmea_sentence.h"

#include <cmath>
#include <cstdio>

namespace hil::gnss::nmea {
namespace {

// Degrees and minutes with the minutes rounded first, so 59.999995' carries into the degrees.
std::string FormatDegreesMinutes(double value_deg, int deg_digits, int decimals, char pos,
                                 char neg) {
  const double abs_deg = std::fabs(value_deg);
  const double scale = std::pow(10.0, decimals);
  auto total = static_cast<long long>(std::llround(abs_deg * 60.0 * scale));  // minutes × scale
  const long long per_degree = static_cast<long long>(60.0 * scale);
  const long long deg = total / per_degree;
  const long long min_scaled = total % per_degree;
  const long long min_int = min_scaled / static_cast<long long>(scale);
  const long long min_frac = min_scaled % static_cast<long long>(scale);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%0*lld%02lld.%0*lld,%c", deg_digits, deg, min_int, decimals,
                min_frac, value_deg < 0 ? neg : pos);
  return buf;
}

}  // namespace

std::uint8_t Checksum(std::string_view body) {
  std::uint8_t sum = 0;
  for (char c : body) sum ^= static_cast<std::uint8_t>(c);
  return sum;
}

std::string Frame(std::string_view body) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  const std::uint8_t sum = Checksum(body);
  std::string out;
  out.reserve(body.size() + 6);
  out += '$';
  out += body;
  out += '*';
  out += kHex[sum >> 4];
  out += kHex[sum & 0x0F];
  out += "\r\n";
  return out;
}

std::string FormatLatitude(double lat_deg, int decimals) {
  return FormatDegreesMinutes(lat_deg, 2, decimals, 'N', 'S');
}

std::string FormatLongitude(double lon_deg, int decimals) {
  return FormatDegreesMinutes(lon_deg, 3, decimals, 'E', 'W');
}

std::string FormatFixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  // "-0.000" → "0.000": a receiver does not print negative zero.
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

}  // namespace hil::gnss::nmea

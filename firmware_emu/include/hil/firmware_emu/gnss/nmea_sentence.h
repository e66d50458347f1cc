#pragma once
/// @file
/// NMEA 0183 framing for the emulators: `$<body>*HH\r\n`, HH the XOR of every byte between `$` and
/// `*` as two uppercase hex digits. Field formatting helpers in the u-blox firmware-6 number
/// formats live here too so every sentence encoder shares them.

#include <cstdint>
#include <string>
#include <string_view>

namespace hil::gnss::nmea {

/// XOR checksum of a sentence body (the bytes between `$` and `*`).
std::uint8_t Checksum(std::string_view body);
/// Frames a body: "$" + body + "*HH\r\n".
std::string Frame(std::string_view body);
/// Latitude as `ddmm.mmmmm,N` (or `,S`); `decimals` digits of minutes.
std::string FormatLatitude(double lat_deg, int decimals = 5);
/// Longitude as `dddmm.mmmmm,E` (or `,W`).
std::string FormatLongitude(double lon_deg, int decimals = 5);
/// Fixed-point number with `decimals` digits, never "-0.00".
std::string FormatFixed(double value, int decimals);

}  // namespace hil::gnss::nmea

#pragma once
/// @file
/// NMEA 0183 sentences of the fused solution, in u-blox order: RMC (position, speed, course, date),
/// GGA (position, quality) and HDT (true heading), each with its checksum and CR LF. Talker "GN".

#include <cstdint>
#include <string>

#include "hil/estimator/navigator.h"

namespace hil::estimator::outputs {

/// The three sentences for one solution; `utc_unix_ns` is its time of validity in UTC.
/// HDT is omitted when the solution has no attitude.
std::string FormatNmea0183(const NavOutput& o, std::int64_t utc_unix_ns);
/// "$<body>*HH\r\n" with the XOR checksum of body.
std::string NmeaSentence(const std::string& body);

}  // namespace hil::estimator::outputs

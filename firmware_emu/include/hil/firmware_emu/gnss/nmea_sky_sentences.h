#pragma once
/// @file
/// NMEA sentences about the sky and the solution geometry, u-blox 5 firmware-6 formats:
/// `$GPGSA` (used satellites in channel order, padded to 12, PDOP/HDOP/VDOP) and `$GPGSV`
/// (satellites in view sorted by PRN, 4 per sentence, SBAS as NMEA 33+, empty C/N0 when not
/// tracked, empty elevation/azimuth without orbit knowledge). Facts: shared/reference/ublox5.md §3.

#include <string>
#include <vector>

#include "hil/firmware_emu/gnss/nav_epoch.h"

namespace hil::gnss::nmea {

/// `$GPGSA`; without a fix navMode 1, no satellites and DOPs 99.99.
std::string EncodeGsa(const NavEpoch& e);
/// `$GPGSV` sentences (one or more; `$GPGSV,1,1,00` when nothing is in view). `max_sv` limits
/// the satellites reported (CFG-NMEA numSV; 0 = unlimited).
std::vector<std::string> EncodeGsv(const NavEpoch& e, int max_sv = 0);

}  // namespace hil::gnss::nmea

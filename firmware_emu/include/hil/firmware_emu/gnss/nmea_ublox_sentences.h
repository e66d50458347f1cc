#pragma once
/// @file
/// u-blox-specific NMEA output: `$GPTXT` (start-up banner, notices) and the proprietary
/// `$PUBX,00` (position) and `$PUBX,04` (time) messages, as documented for u-blox receivers
/// (shared/reference/ublox5.md §3.3; the u-blox 5 decimals are UNVERIFIED, the formats follow the
/// u-blox example sentences).

#include <string>

#include "hil/firmware_emu/gnss/nav_epoch.h"

namespace hil::gnss::nmea {

/// `$GPTXT,01,01,<type>,<text>`; type 02 = notice.
std::string EncodeTxt(const std::string& text, int type = 2, int total = 1, int number = 1);
/// `$PUBX,00,...` — time, lat/lon (6 decimals of minutes), altitude above the ellipsoid, navStat
/// (NF, G2, G3, D2, D3), hAcc, vAcc, SOG (km/h), COG, vVel (m/s, positive down), diffAge, HDOP,
/// VDOP, TDOP, numSvs, reserved, DR.
std::string EncodePubx00(const NavEpoch& e);
/// `$PUBX,04,...` — UTC time and date, UTC time of week, week, leap seconds (suffix `D` while the
/// firmware default is used), clock bias (ns), clock drift (ns/s), time pulse granularity (ns).
std::string EncodePubx04(const NavEpoch& e);

}  // namespace hil::gnss::nmea

#pragma once
/// @file
/// The NMEA output of a u-blox F9 (NMEA 4.10, its default): the fix sentences with the combined
/// talker GN (GGA, RMC, VTG, GLL, GSA), the satellites' GSV with the talker of their constellation
/// (GP for GPS and SBAS), RMC's navStatus field (V: the receiver gives no navigational status),
/// GSA's systemId (1: GPS) and GSV's signalId (1: GPS L1C/A), and GGA's quality 4 (RTK fixed) or
/// 5 (RTK float) with the age of the corrections and the base's station id. Built on the u-blox 5
/// encoders (nmea_encoder.h, nmea_sky_sentences.h): the fields they share are the same.

#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/gnss/nav_epoch.h"
#include "hil/firmware_emu/gnss/nmea_encoder.h"

namespace hil::gnss::nmea {

/// A framed sentence with its talker replaced and `extra` fields appended (each after a comma).
std::string Amend(std::string_view sentence, std::string_view talker,
                  const std::vector<std::string>& extra = {});
/// `$GNGGA`: with corrections (age ≥ 0) the age in seconds (one decimal) and the station id
/// (four digits); otherwise both fields empty.
std::string EncodeF9Gga(const GnssFix& fix, bool time_known, double correction_age_s,
                        int station_id);
/// `$GNRMC` (NMEA 4.10: navStatus V appended).
std::string EncodeF9Rmc(const GnssFix& fix, bool time_known);
std::string EncodeF9Vtg(const GnssFix& fix);
std::string EncodeF9Gll(const GnssFix& fix, bool time_known);
/// `$GNGSA` with systemId 1.
std::string EncodeF9Gsa(const NavEpoch& e);
/// `$GPGSV` with signalId 1.
std::vector<std::string> EncodeF9Gsv(const NavEpoch& e);

}  // namespace hil::gnss::nmea

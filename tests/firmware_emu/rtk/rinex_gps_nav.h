#pragma once
// A RINEX 3.04 GPS navigation file of our constellation (Constellation::Ephemeris): the broadcast
// ephemeris an RTK engine needs beside the observations. A u-blox base (ZED-F9P in base mode)
// sends no RTCM 1019: its users' post-processing takes the ephemeris from the rover's own
// RXM-SFRBX, which the emulator does not produce, so the judge writes the same orbits as a
// navigation file (RINEX 3.04, §A8 of the format: one record per satellite, eight lines).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/gps_time.h"

namespace hil::rtk::test {

inline std::string NavField(double v) {
  char b[24];
  std::snprintf(b, sizeof b, "%19.12E", v);
  return b;
}

inline std::string NavLine(double a, double b, double c, double d) {
  return "    " + NavField(a) + NavField(b) + NavField(c) + NavField(d) + "\n";
}

/// Writes every orbit's ephemeris with reference time `toe_utc` (its GPS time) to `file`.
inline void WriteRinexGpsNav(const std::string& file, const gnss::Constellation& sky,
                             UnixTime toe_utc) {
  const gnss::GpsWeekTime gps = gnss::GpsFrom(toe_utc);
  const double toe_gps_s = gps.week * 604800.0 + gps.tow_s();
  // the epoch of the clock (t_oc = t_oe) as a calendar date in GPS time (UTC + leap seconds)
  const gnss::UtcTime c =
      gnss::UtcFrom(toe_utc + std::chrono::seconds(gnss::LeapSecondsAt(toe_utc)));
  std::ofstream out(file);
  char line[96];
  std::snprintf(line, sizeof line, "%9.2f%11s%-20s%-20s%-20s\n", 3.04, "", "N: GNSS NAV DATA",
                "G: GPS", "RINEX VERSION / TYPE");
  out << line;
  std::snprintf(line, sizeof line, "%-20s%-20s%-20s%-20s\n", "hil", "hil", "",
                "PGM / RUN BY / DATE");
  out << line << std::string(60, ' ') << "END OF HEADER\n";
  for (std::size_t i = 0; i < sky.gps_count(); ++i) {
    const gnss::GpsEphemeris e = sky.Ephemeris(i, toe_gps_s);
    std::snprintf(line, sizeof line, "G%02d %04d %02d %02d %02d %02d %02d", e.svid, c.year, c.month,
                  c.day, c.hour, c.minute, c.second);
    out << line << NavField(0) << NavField(0) << NavField(0) << "\n";  // a_f0, a_f1, a_f2
    out << NavLine(1, 0, 0, e.m0_rad);                                 // IODE, Crs, Δn, M0
    out << NavLine(0, 0, 0, e.sqrt_a);                                 // Cuc, e, Cus, √A
    out << NavLine(e.toe_s, 0, e.omega0_rad, 0);                       // t_oe, Cic, Ω0, Cis
    out << NavLine(e.i0_rad, 0, 0, 0);                                 // i0, Crc, ω, Ω̇
    out << NavLine(0, 1, e.week, 0);                                   // IDOT, L2 codes, week
    out << NavLine(2.0, 0, 0, 1);                                      // URA (m), health, TGD, IODC
    out << "    " + NavField(e.toe_s) + NavField(4) + "\n";            // t_tm, fit interval (h)
  }
}

}  // namespace hil::rtk::test

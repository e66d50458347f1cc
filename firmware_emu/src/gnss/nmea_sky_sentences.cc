#include "hil/firmware_emu/gnss/nmea_sky_sentences.h"

#include <cmath>
#include <cstdio>

#include "hil/firmware_emu/gnss/nmea_sentence.h"

namespace hil::gnss::nmea {

std::string EncodeGsa(const NavEpoch& e) {
  const bool valid = e.fix.valid();
  std::string b = "GPGSA,A,";
  b += !valid ? "1" : e.fix.fix_type == FixType::k2D ? "2" : "3";
  std::size_t n = 0;
  if (valid) {
    for (int svid : e.used_in_channel_order) {
      if (n == 12) break;
      char buf[8];
      std::snprintf(buf, sizeof buf, ",%02d", svid);
      b += buf;
      ++n;
    }
  }
  for (; n < 12; ++n) b += ",";
  if (valid)
    b += "," + FormatFixed(e.fix.pdop, 2) + "," + FormatFixed(e.fix.hdop, 2) + "," +
         FormatFixed(e.fix.vdop, 2);
  else
    b += ",99.99,99.99,99.99";
  return Frame(b);
}

std::vector<std::string> EncodeGsv(const NavEpoch& e, int max_sv) {
  std::vector<const SatelliteView*> list;
  for (const auto& s : e.sats) {
    // without orbit knowledge the receiver knows only the satellites it tracks
    if (!s.orbit_known && !s.tracked) continue;
    if (max_sv > 0 && static_cast<int>(list.size()) >= max_sv) break;
    list.push_back(&s);
  }
  std::vector<std::string> out;
  if (list.empty()) {
    out.push_back(Frame("GPGSV,1,1,00"));
    return out;
  }
  const std::size_t total = (list.size() + 3) / 4;
  for (std::size_t k = 0; k < total; ++k) {
    char head[80];
    std::snprintf(head, sizeof head, "GPGSV,%zu,%zu,%02zu", total, k + 1, list.size());
    std::string b = head;
    for (std::size_t i = 4 * k; i < list.size() && i < 4 * k + 4; ++i) {
      const SatelliteView& s = *list[i];
      char buf[32];
      std::snprintf(buf, sizeof buf, ",%02d,", s.nmea_id());
      b += buf;
      if (s.orbit_known) {
        std::snprintf(buf, sizeof buf, "%02ld,%03ld,", std::lround(s.elev_deg),
                      std::lround(s.azim_deg) % 360);
        b += buf;
      } else {
        b += ",,";
      }
      if (s.tracked && s.cno_dbhz > 0) {
        std::snprintf(buf, sizeof buf, "%02d", s.cno_dbhz);
        b += buf;
      }
    }
    out.push_back(Frame(b));
  }
  return out;
}

}  // namespace hil::gnss::nmea

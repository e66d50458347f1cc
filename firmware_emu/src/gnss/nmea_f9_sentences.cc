#include "hil/firmware_emu/gnss/nmea_f9_sentences.h"

#include <cstdio>

#include "hil/firmware_emu/gnss/nmea_sentence.h"
#include "hil/firmware_emu/gnss/nmea_sky_sentences.h"

namespace hil::gnss::nmea {
namespace {

// NMEA 4.10 posMode of an RTK solution (R fixed, F float) in place of the u-blox 5's D: the
// mode is the last field of the u-blox 5 RMC, VTG and GLL.
std::string WithRtkMode(std::string sentence, const GnssFix& fix) {
  const std::size_t star = sentence.rfind('*');
  if (!fix.valid() || star < 2) return sentence;
  if (fix.quality == FixQuality::kRtkFixed) sentence[star - 1] = 'R';
  if (fix.quality == FixQuality::kRtkFloat) sentence[star - 1] = 'F';
  return sentence;
}

}  // namespace

std::string Amend(std::string_view sentence, std::string_view talker,
                  const std::vector<std::string>& extra) {
  const std::size_t star = sentence.rfind('*');
  std::string body(sentence.substr(1, star - 1));
  body.replace(0, 2, talker);
  for (const std::string& f : extra) body += "," + f;
  return Frame(body);
}

std::string EncodeF9Gga(const GnssFix& fix, bool time_known, double correction_age_s,
                        int station_id) {
  const std::string gga = EncodeGga(fix, time_known, NmeaFormat{});
  const std::size_t star = gga.rfind('*');
  std::string body = gga.substr(1, star - 1);
  body.replace(0, 2, "GN");
  if (fix.valid() && correction_age_s >= 0) {
    // the last two fields (age of the corrections, station id) are empty in EncodeGga's output
    body.erase(body.size() - 1);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f,%04d", correction_age_s, station_id % 10000);
    body += buf;
  }
  return Frame(body);
}

std::string EncodeF9Rmc(const GnssFix& fix, bool time_known) {
  return Amend(WithRtkMode(EncodeRmc(fix, time_known, NmeaFormat{}), fix), "GN", {"V"});
}

std::string EncodeF9Vtg(const GnssFix& fix) {
  return Amend(WithRtkMode(EncodeVtg(fix, NmeaFormat{}), fix), "GN");
}

std::string EncodeF9Gll(const GnssFix& fix, bool time_known) {
  return Amend(WithRtkMode(EncodeGll(fix, time_known, NmeaFormat{}), fix), "GN");
}

std::string EncodeF9Gsa(const NavEpoch& e) { return Amend(EncodeGsa(e), "GN", {"1"}); }

std::vector<std::string> EncodeF9Gsv(const NavEpoch& e) {
  std::vector<std::string> out;
  for (const std::string& s : EncodeGsv(e)) out.push_back(Amend(s, "GP", {"1"}));
  return out;
}

}  // namespace hil::gnss::nmea

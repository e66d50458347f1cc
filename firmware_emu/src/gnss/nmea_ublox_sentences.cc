#include "hil/firmware_emu/gnss/nmea_ublox_sentences.h"

#include <cmath>
#include <cstdio>

#include "hil/firmware_emu/gnss/nmea_encoder.h"
#include "hil/firmware_emu/gnss/nmea_sentence.h"

namespace hil::gnss::nmea {

std::string EncodeTxt(const std::string& text, int type, int total, int number) {
  char head[32];
  std::snprintf(head, sizeof head, "GPTXT,%02d,%02d,%02d,", total, number, type);
  return Frame(std::string(head) + text);
}

std::string EncodePubx00(const NavEpoch& e) {
  const GnssFix& f = e.fix;
  const bool valid = f.valid();
  std::string b = "PUBX,00,";
  b += e.status.time_known ? FormatTime(f.utc) : "";
  b += ",";
  if (e.position_known)
    b += FormatLatitude(f.lat_deg, 6) + "," + FormatLongitude(f.lon_deg, 6);
  else
    b += "0000.000000,N,00000.000000,E";
  b += "," + FormatFixed(e.position_known ? f.height_m : 0.0, 3) + ",";
  if (!valid)
    b += "NF";
  else
    b += std::string(f.quality == FixQuality::kGps ? "G" : "D") +
         (f.fix_type == FixType::k2D ? "2" : "3");
  const double h_acc = valid ? f.h_acc_m : 9999.0, v_acc = valid ? f.v_acc_m : 9999.0;
  b += "," + FormatFixed(h_acc, 1) + "," + FormatFixed(v_acc, 1) + ",";
  const double speed = valid ? f.ground_speed_mps() : 0.0;
  b += FormatFixed(speed * 3.6, 3) + ",";
  b += FormatFixed(valid && speed >= kCourseMinSpeed_mps ? f.course_deg() : 0.0, 2) + ",";
  b += FormatFixed(valid ? f.vel_d_mps : 0.0, 3) + ",";
  b += e.sbas_corrections && valid ? "1," : ",";
  b += FormatFixed(valid ? f.hdop : 99.99, 2) + "," + FormatFixed(valid ? f.vdop : 99.99, 2) + "," +
       FormatFixed(valid ? f.tdop : 99.99, 2) + ",";
  b += std::to_string(valid ? f.num_sv : 0) + ",0,0";
  return Frame(b);
}

std::string EncodePubx04(const NavEpoch& e) {
  const GnssFix& f = e.fix;
  std::string b = "PUBX,04,";
  b += FormatTime(f.utc) + "," + FormatDate(f.utc) + ",";
  // UTC time of week: GPS time of week minus the leap seconds, wrapped into the week
  double utc_tow = e.gps.tow_s() - e.leap_s;
  int utc_week = e.gps.week;
  if (utc_tow < 0) {
    utc_tow += 604800.0;
    --utc_week;
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2f,%d,%d%s,%ld,", utc_tow, utc_week, e.leap_s,
                e.leap_known ? "" : "D", std::lround(e.clk_bias_ns));
  b += buf;
  b += FormatFixed(e.clk_drift_nsps, 3) + ",";
  b += "43,";  // time pulse granularity (ns), the value of the u-blox example
  return Frame(b);
}

}  // namespace hil::gnss::nmea

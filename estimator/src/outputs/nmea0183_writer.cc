#include "hil/estimator/outputs/nmea0183_writer.h"

#include <cmath>
#include <cstdio>

namespace hil::estimator::outputs {
namespace {

void CivilFromDays(std::int64_t z, int& y, int& m, int& d) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  y = static_cast<int>(yoe + era * 400 + (m <= 2));
}

std::string LatLon(double deg, bool is_lat) {
  const char hemi = is_lat ? (deg >= 0 ? 'N' : 'S') : (deg >= 0 ? 'E' : 'W');
  deg = std::abs(deg);
  int whole = static_cast<int>(deg);
  double minutes = (deg - whole) * 60.0;
  if (minutes >= 59.9999995) {
    minutes = 0;
    ++whole;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, is_lat ? "%02d%010.7f,%c" : "%03d%010.7f,%c", whole, minutes,
                hemi);
  return buf;
}

}  // namespace

std::string NmeaSentence(const std::string& body) {
  unsigned char x = 0;
  for (char c : body) x = static_cast<unsigned char>(x ^ static_cast<unsigned char>(c));
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", x);
  return "$" + body + tail;
}

std::string FormatNmea0183(const NavOutput& o, std::int64_t utc_unix_ns) {
  const std::int64_t day_ns = 86400LL * 1000000000LL;
  std::int64_t days = utc_unix_ns / day_ns, tod = utc_unix_ns % day_ns;
  if (tod < 0) {
    tod += day_ns;
    --days;
  }
  const std::int64_t cs = tod / 10000000;  // centiseconds
  char time[16];
  std::snprintf(time, sizeof time, "%02lld%02lld%02lld.%02lld", static_cast<long long>(cs / 360000),
                static_cast<long long>(cs / 6000 % 60), static_cast<long long>(cs / 100 % 60),
                static_cast<long long>(cs % 100));
  int y = 0, m = 0, d = 0;
  CivilFromDays(days, y, m, d);
  const std::string lat = LatLon(o.position.lat_deg, true), lon = LatLon(o.position.lon_deg, false);
  char buf[256];
  // a speed without a direction (the receiver gave no course) keeps the course field empty
  const double speed_mps =
      o.has_velocity ? o.v_N_mps.head<2>().norm() : o.ground_speed_mps.value_or(0.0);
  char course[16] = "";
  if (o.has_velocity) {
    double c = std::atan2(o.v_N_mps.x(), o.v_N_mps.y()) * 180.0 / M_PI;
    if (c < 0) c += 360.0;
    std::snprintf(course, sizeof course, "%.2f", c);
  }
  std::snprintf(buf, sizeof buf, "GNRMC,%s,%c,%s,%s,%.3f,%s,%02d%02d%02d,,,%c", time,
                o.valid ? 'A' : 'V', lat.c_str(), lon.c_str(), speed_mps / 0.514444, course, d, m,
                y % 100, o.valid ? 'A' : 'N');
  std::string out = NmeaSentence(buf);
  // GGA: the ellipsoidal height as altitude with a zero geoid separation (the filter has no geoid)
  std::snprintf(buf, sizeof buf, "GNGGA,%s,%s,%s,%d,08,1.0,%.3f,M,0.0,M,,", time, lat.c_str(),
                lon.c_str(), o.valid ? 1 : 0, o.position.height_m);
  out += NmeaSentence(buf);
  if (o.has_attitude) {
    const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX();
    double hdg = 90.0 - std::atan2(x.y(), x.x()) * 180.0 / M_PI;
    hdg = std::fmod(hdg + 360.0, 360.0);
    std::snprintf(buf, sizeof buf, "GNHDT,%.2f,T", hdg);
    out += NmeaSentence(buf);
  }
  return out;
}

}  // namespace hil::estimator::outputs

#include "hil/estimator/navd/nav_solution.h"

#include <cstdio>

namespace hil::estimator {

std::string ToJsonLine(const NavSolution& s) {
  char buf[768];
  const long long sec = s.tov_unix_ns / 1000000000LL;
  const long long nsec = s.tov_unix_ns % 1000000000LL;
  int n = std::snprintf(buf, sizeof buf,
                        "{\"tov_utc_s\":%lld.%09lld,\"tov_unix_ns\":%lld,\"lat_deg\":%.10f,"
                        "\"lon_deg\":%.10f,\"height_m\":%.4f",
                        sec, nsec, static_cast<long long>(s.tov_unix_ns), s.lat_deg, s.lon_deg,
                        s.height_m);
  std::string out(buf, static_cast<std::size_t>(n));
  if (s.vel_enu_mps) {
    const auto& v = *s.vel_enu_mps;
    n = std::snprintf(buf, sizeof buf, ",\"vel_enu_mps\":[%.4f,%.4f,%.4f]", v[0], v[1], v[2]);
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (s.speed_mps) {
    n = std::snprintf(buf, sizeof buf, ",\"speed_mps\":%.4f", *s.speed_mps);
    out.append(buf, static_cast<std::size_t>(n));
  }
  n = std::snprintf(buf, sizeof buf, ",\"pos_std_enu_m\":[%.4f,%.4f,%.4f]", s.pos_std_enu_m[0],
                    s.pos_std_enu_m[1], s.pos_std_enu_m[2]);
  out.append(buf, static_cast<std::size_t>(n));
  if (s.yaw_deg) {
    n = std::snprintf(buf, sizeof buf, ",\"yaw_deg\":%.4f", *s.yaw_deg);
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (s.roll_deg && s.pitch_deg) {
    n = std::snprintf(buf, sizeof buf, ",\"roll_deg\":%.4f,\"pitch_deg\":%.4f", *s.roll_deg,
                      *s.pitch_deg);
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (s.vel_std_enu_mps) {
    const auto& v = *s.vel_std_enu_mps;
    n = std::snprintf(buf, sizeof buf, ",\"vel_std_enu_mps\":[%.4f,%.4f,%.4f]", v[0], v[1], v[2]);
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (s.nis_pos) {
    n = std::snprintf(buf, sizeof buf, ",\"nis_pos\":%.3f", *s.nis_pos);
    out.append(buf, static_cast<std::size_t>(n));
  }
  if (s.mean_nis_pos) {
    n = std::snprintf(buf, sizeof buf, ",\"mean_nis_pos\":%.3f", *s.mean_nis_pos);
    out.append(buf, static_cast<std::size_t>(n));
  }
  n = std::snprintf(buf, sizeof buf, ",\"mode\":\"%s\",\"status\":%u}\n", s.mode.c_str(),
                    s.status_flags);
  out.append(buf, static_cast<std::size_t>(n));
  return out;
}

}  // namespace hil::estimator

#include "gpsd_chk.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace hil::estimator::testing {
namespace {

std::int64_t DaysFromCivil(int y, int m, int d) {
  y -= m <= 2;
  const int era = (y >= 0 ? y : y - 399) / 400;
  const int yoe = y - era * 400;
  const int doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  return static_cast<std::int64_t>(era) * 146097 + yoe * 365 + yoe / 4 - yoe / 100 + doy - 719468;
}

void Merge(GpsdEpoch& e, const nlohmann::json& j) {
  e.mode = std::max(e.mode, j.value("mode", 0));
  const auto take = [&](const char* key, std::optional<double>& v) {
    if (j.contains(key) && j[key].is_number()) v = j[key].get<double>();
  };
  take("lat", e.lat_deg);
  take("lon", e.lon_deg);
  take("altHAE", e.alt_hae_m);
  take("speed", e.speed_mps);
  take("track", e.track_deg);
}

}  // namespace

std::string GpsdVectorsDir() { return HIL_GPSD_VECTORS_DIR; }

const std::vector<GpsdLog>& GpsdLogs() {
  static const std::vector<GpsdLog> logs = {{"ublox-lea-5h.log", "nmea"},
                                            {"nl551e.log", "nmea"},
                                            {"nl402u.log", "nmea"},
                                            {"ublox-lea-5q.log", "nmea"},
                                            {"navisys-gr701w.log", "ubx"}};
  return logs;
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::int64_t UnixNsFromIso(const std::string& iso) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, ms = 0;
  double sec = 0;
  if (std::sscanf(iso.c_str(), "%d-%d-%dT%d:%d:%lfZ", &y, &mo, &d, &h, &mi, &sec) != 6)
    throw std::runtime_error("time \"" + iso + "\" is not YYYY-MM-DDTHH:MM:SS.sssZ");
  ms = static_cast<int>(sec * 1000.0 + 0.5);
  return ((DaysFromCivil(y, mo, d) * 86400 + h * 3600 + mi * 60) * 1000 + ms) * 1'000'000LL;
}

GpsdReport ReadGpsdChk(const std::string& chk_path) {
  std::istringstream in(ReadBytes(chk_path));
  std::map<std::int64_t, GpsdEpoch> by_time;
  GpsdReport r;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty() || line[0] != '{') continue;  // gpsd's NMEA lines
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      throw std::runtime_error(chk_path + ":" + std::to_string(line_no) + ": not a JSON object");
    if (j.value("class", "") != "TPV") continue;
    if (!j.contains("time")) {
      ++r.timeless_tpvs;
      continue;
    }
    const std::int64_t t = UnixNsFromIso(j["time"].get<std::string>());
    GpsdEpoch& e = by_time[t];
    e.unix_ns = t;
    Merge(e, j);
  }
  for (const auto& [t, e] : by_time) r.epochs.push_back(e);
  return r;
}

}  // namespace hil::estimator::testing

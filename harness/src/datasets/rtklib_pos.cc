#include "hil/harness/datasets/rtklib_pos.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <map>

#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {
namespace {

// where each quantity is, counted after the time field(s)
struct PosFileColumns {
  bool calendar = true;  // yyyy/mm/dd hh:mm:ss (2 tokens) or week tow (2 tokens)
  std::map<std::string, int> at;
  int Need(const std::string& name, const std::string& path, long line) const {
    const auto it = at.find(name);
    if (it == at.end()) throw ImportInputError(path, line, name, "column missing from the header");
    return it->second;
  }
};

PosFileColumns ParsePosHeader(std::string_view header, const std::string& path, long line) {
  header.remove_prefix(1);  // '%'
  const std::vector<std::string_view> names = SplitFields(header, false);
  if (names.empty() || names[0] != "GPST")
    throw ImportInputError(
        path, line, "time system",
        names.empty() ? "no header" : "'" + std::string(names[0]) + "' (only GPST is read)");
  PosFileColumns c;
  for (std::size_t i = 1; i < names.size(); ++i) {
    std::string n(names[i]);
    if (const auto p = n.find('('); p != std::string::npos) n.resize(p);
    c.at[n] = static_cast<int>(i) + 1;  // the time takes two tokens
  }
  if (!c.at.count("latitude"))
    throw ImportInputError(path, line, "header", "not a geodetic (lat/lon/height) solution");
  return c;
}

double PosField(const std::vector<std::string_view>& f, int i, const std::string& name,
                const std::string& path, long line) {
  if (i >= static_cast<int>(f.size())) throw ImportInputError(path, line, name, "missing");
  return ParseFiniteField(f[static_cast<std::size_t>(i)], path, line, name);
}

void ParsePosTime(const std::vector<std::string_view>& f, RtklibPosEpoch& e,
                  const std::string& path, long line) {
  if (f.size() < 2) throw ImportInputError(path, line, "GPST", "missing");
  if (f[0].find('/') == std::string_view::npos) {  // week and seconds of week
    e.week = static_cast<int>(PosField(f, 0, "GPST week", path, line));
    e.sow = PosField(f, 1, "GPST seconds of week", path, line);
    return;
  }
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double s = 0;
  const std::string txt = std::string(f[0]) + " " + std::string(f[1]);
  char tail = 0;
  if (std::sscanf(txt.c_str(), "%d/%d/%d %d:%d:%lf%c", &y, &mo, &d, &h, &mi, &s, &tail) != 6 ||
      mo < 1 || mo > 12 || d < 1 || d > 31 || h < 0 || h > 23 || mi < 0 || mi > 59 || s < 0 ||
      s >= 61)
    throw ImportInputError(path, line, "GPST", "'" + txt + "' is not yyyy/mm/dd hh:mm:ss.sss");
  const GpsWeekSow g = GpsFromCalendar(y, mo, d, h, mi, s);
  e.week = g.week;
  e.sow = g.sow;
}

RtklibPosEpoch ParsePosEpoch(const std::vector<std::string_view>& f, const PosFileColumns& c,
                             const std::string& path, long line) {
  RtklibPosEpoch e;
  ParsePosTime(f, e, path, line);
  const auto get = [&](const char* name) {
    return PosField(f, c.Need(name, path, line), name, path, line);
  };
  e.lat_deg = get("latitude");
  e.lon_deg = get("longitude");
  e.height_m = get("height");
  if (e.lat_deg < -90 || e.lat_deg > 90)
    throw ImportInputError(path, line, "latitude", "outside ±90°");
  e.quality = static_cast<int>(get("Q"));
  e.satellites = static_cast<int>(get("ns"));
  e.std_ned_m = {get("sdn"), get("sde"), get("sdu")};
  if (c.at.count("vn")) {
    e.has_velocity = true;
    e.v_ned_mps = {get("vn"), get("ve"), -get("vu")};
    e.v_std_ned_mps = {get("sdvn"), get("sdve"), get("sdvu")};
  }
  if ((e.std_ned_m.array() < 0).any() || (e.v_std_ned_mps.array() < 0).any())
    throw ImportInputError(path, line, "sd", "negative standard deviation");
  return e;
}

}  // namespace

std::vector<RtklibPosEpoch> ReadRtklibPos(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  std::vector<RtklibPosEpoch> out;
  std::string line, header;
  long n = 0, header_line = 0;
  PosFileColumns cols;
  bool have_cols = false;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (line[0] == '%') {
      header = line;
      header_line = n;
      continue;
    }
    if (!have_cols) {
      if (header.empty()) throw ImportInputError(path, n, "header", "no '%  GPST ...' column line");
      cols = ParsePosHeader(header, path, header_line);
      have_cols = true;
    }
    RtklibPosEpoch e = ParsePosEpoch(SplitFields(line, false), cols, path, n);
    if (!out.empty() &&
        (e.week * 604800.0 + e.sow) <= (out.back().week * 604800.0 + out.back().sow))
      throw ImportInputError(path, n, "GPST", "time repeats or goes backwards");
    out.push_back(e);
  }
  if (out.empty()) throw ImportInputError(path, 0, "", "no solution epochs");
  return out;
}

}  // namespace hil::harness

#include "hil/harness/datasets/outage_windows.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {

std::vector<OutageWindow> PlanOutages(const OutagePlan& p, double t0, double t_end) {
  if (p.length_s <= 0) throw std::invalid_argument("outage length must be > 0 s");
  std::vector<double> starts = p.at_s;
  if (p.every_s > 0) {
    if (p.every_s <= p.length_s)
      throw std::invalid_argument("outage period must be longer than the outage length");
    for (double s = p.first_s; t0 + s + p.length_s < t_end; s += p.every_s) starts.push_back(s);
  }
  std::sort(starts.begin(), starts.end());
  std::vector<OutageWindow> w;
  for (double s : starts) {
    if (t0 + s + p.length_s >= t_end) continue;
    if (!w.empty() && t0 + s < w.back().end_s)
      throw std::invalid_argument("outage windows overlap");
    w.push_back({t0 + s, t0 + s + p.length_s});
  }
  return w;
}

bool InOutage(const std::vector<OutageWindow>& w, double t) {
  return std::any_of(w.begin(), w.end(),
                     [t](const OutageWindow& o) { return t >= o.start_s && t < o.end_s; });
}

void WriteOutageWindows(const std::string& path, const std::vector<OutageWindow>& w) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot create");
  std::fprintf(
      f, "# GNSS outage windows: start end (GPS seconds of week); fixes dropped in [start, end)\n");
  for (const OutageWindow& o : w) std::fprintf(f, "%.3f %.3f\n", o.start_s, o.end_s);
  if (std::fclose(f) != 0) throw std::runtime_error(path + ": write error");
}

std::vector<OutageWindow> ReadOutageWindows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  std::vector<OutageWindow> w;
  std::string line;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    const std::vector<std::string_view> f = SplitFields(line, false);
    if (f.empty() || f[0][0] == '#') continue;
    if (f.size() != 2) throw ImportInputError(path, n, "window", "expected start and end");
    OutageWindow o{ParseFiniteField(f[0], path, n, "start"),
                   ParseFiniteField(f[1], path, n, "end")};
    if (o.end_s <= o.start_s) throw ImportInputError(path, n, "end", "not after the start");
    if (!w.empty() && o.start_s < w.back().end_s)
      throw ImportInputError(path, n, "start", "before the previous window's end");
    w.push_back(o);
  }
  return w;
}

}  // namespace hil::harness

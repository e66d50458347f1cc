#include "hil/harness/datasets/imu_csv.h"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {
namespace {

constexpr const char* kCsvAxes[] = {"x", "y", "z"};

// false when the line has too few fields (a cut line)
bool ParseCsvSample(std::string_view text, const ImuCsvOptions& o, const std::string& path, long n,
                    ImuCsvSample& s) {
  const std::vector<std::string_view> f = SplitFields(text, true);
  const int need = std::max({o.accel_column + 3, o.gyro_column + 3, o.tick_column + 1});
  if (static_cast<int>(f.size()) < need) return false;
  for (int k = 0; k < 3; ++k) {
    s.f_sensor_mps2[k] = o.accel_scale * ParseFiniteField(f[o.accel_column + k], path, n,
                                                          std::string("accel ") + kCsvAxes[k]);
    s.w_sensor_radps[k] = o.gyro_scale * ParseFiniteField(f[o.gyro_column + k], path, n,
                                                          std::string("gyro ") + kCsvAxes[k]);
  }
  s.tick_s = o.tick_s * ParseFiniteField(f[o.tick_column], path, n, "tick");
  return true;
}

}  // namespace

ImuCsv ReadImuCsv(const std::string& path, const ImuCsvOptions& o) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ImuCsv out;
  out.file_bytes = text.size();
  out.has_cr = text.find('\r') != std::string::npos;
  out.newlines = static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\n'));
  std::size_t pos = 0;
  long n = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    const bool last = nl == std::string::npos || nl + 1 == text.size();
    const std::size_t end = nl == std::string::npos ? text.size() : nl + 1;
    std::string_view line(text.data() + pos, end - pos);
    ++n;
    pos = end;
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
    if (line.empty()) continue;
    ImuCsvSample s;
    s.line = n;
    s.end_pos = end;
    const bool whole = ParseCsvSample(line, o, path, n, s) && nl != std::string::npos;
    if (!whole && (n == 1 || last)) {
      ++out.cut_lines;
      continue;
    }
    if (!whole) throw ImportInputError(path, n, "fields", "too few (a cut line inside the log)");
    if (!out.samples.empty() && s.tick_s <= out.samples.back().tick_s)
      throw ImportInputError(path, n, "tick", "does not increase");
    out.samples.push_back(s);
  }
  out.lines = n;
  if (out.samples.size() < 2) throw ImportInputError(path, 0, "", "fewer than two samples");
  return out;
}

}  // namespace hil::harness

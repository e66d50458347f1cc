#include "hil/harness/datasets/import_fields.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace hil::harness {

ImportInputError::ImportInputError(const std::string& path, long line, const std::string& field,
                                   const std::string& problem)
    : std::runtime_error(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         (field.empty() ? std::string() : field + ": ") + problem) {}

std::vector<std::string_view> SplitFields(std::string_view line, bool commas) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  if (commas) {
    while (i <= line.size()) {
      std::size_t j = line.find(',', i);
      if (j == std::string_view::npos) j = line.size();
      std::string_view f = line.substr(i, j - i);
      while (!f.empty() && blank(f.front())) f.remove_prefix(1);
      while (!f.empty() && blank(f.back())) f.remove_suffix(1);
      out.push_back(f);
      i = j + 1;
    }
    return out;
  }
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    std::size_t j = i;
    while (j < line.size() && !blank(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

double ParseFiniteField(std::string_view text, const std::string& path, long line,
                        const std::string& field) {
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, v);
  if (text.empty()) throw ImportInputError(path, line, field, "missing");
  if (ec != std::errc() || p != end || !std::isfinite(v))
    throw ImportInputError(path, line, field, "'" + std::string(text) + "' is not a finite number");
  return v;
}

namespace {

// days from 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's days_from_civil)
std::int64_t DaysFromCivil(int y, int m, int d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const int yoe = static_cast<int>(y - era * 400);
  const int doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

constexpr double kFieldsGpsEpochUnix_s = 315964800.0;  // 1980-01-06 00:00:00
constexpr double kFieldsWeek_s = 604800.0;

}  // namespace

GpsWeekSow GpsFromGpstEpochSeconds(double t_s) {
  const double since = t_s - kFieldsGpsEpochUnix_s;
  GpsWeekSow g;
  g.week = static_cast<int>(std::floor(since / kFieldsWeek_s));
  g.sow = since - g.week * kFieldsWeek_s;
  return g;
}

GpsWeekSow GpsFromCalendar(int year, int month, int day, int hour, int minute, double second) {
  // whole seconds as integers, the fraction added last (no rounding of 1e9-second sums)
  const double whole = std::floor(second);
  const std::int64_t t = DaysFromCivil(year, month, day) * 86400 + hour * 3600 + minute * 60 +
                         static_cast<std::int64_t>(whole) -
                         static_cast<std::int64_t>(kFieldsGpsEpochUnix_s);
  const std::int64_t week = t >= 0 ? t / 604800 : (t - 604799) / 604800;
  GpsWeekSow g;
  g.week = static_cast<int>(week);
  g.sow = static_cast<double>(t - week * 604800) + (second - whole);
  return g;
}

}  // namespace hil::harness

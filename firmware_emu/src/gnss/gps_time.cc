#include "hil/firmware_emu/gnss/gps_time.h"

#include <array>
#include <cstdio>
#include <stdexcept>

namespace hil::gnss {
namespace {

constexpr std::int64_t kNsPerSecond = 1000000000;
constexpr std::int64_t kSecondsPerDay = 86400;

std::int64_t FloorDiv(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

// Unix seconds at which GPS − UTC stepped to the given value (IERS Bulletin C).
struct LeapStep {
  std::int64_t unix_s;
  int gps_minus_utc_s;
};
constexpr std::array<LeapStep, 18> kLeapSteps{{
    {362793600, 1},
    {394329600, 2},
    {425865600, 3},
    {489024000, 4},
    {567993600, 5},
    {631152000, 6},
    {662688000, 7},
    {709948800, 8},
    {741484800, 9},
    {773020800, 10},
    {820454400, 11},
    {867715200, 12},
    {915148800, 13},
    {1136073600, 14},
    {1230768000, 15},
    {1341100800, 16},
    {1435708800, 17},
    {1483228800, 18},
}};

// Days of a Gregorian month (month 1–12).
int DaysInMonth(int year, int month) {
  constexpr std::array<int, 12> kDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[static_cast<std::size_t>(month - 1)];
}

}  // namespace

std::int64_t DaysFromCivil(int year, int month, int day) {
  // Howard Hinnant's days_from_civil algorithm.
  const std::int64_t y = year - (month <= 2 ? 1 : 0);
  const std::int64_t era = FloorDiv(y, 400);
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

UnixTime UnixTimeFromUtc(const UtcTime& utc) {
  const std::int64_t days = DaysFromCivil(utc.year, utc.month, utc.day);
  const std::int64_t s = days * kSecondsPerDay + utc.hour * 3600 + utc.minute * 60 + utc.second;
  return UnixTimeFromNs(s * kNsPerSecond + utc.nanosecond);
}

UtcTime UtcFrom(UnixTime t) {
  const std::int64_t unix_ns = ToNs(t);
  const std::int64_t s = FloorDiv(unix_ns, kNsPerSecond);
  const std::int64_t days = FloorDiv(s, kSecondsPerDay);
  const std::int64_t sod = s - days * kSecondsPerDay;
  // civil_from_days
  const std::int64_t z = days + 719468;
  const std::int64_t era = FloorDiv(z, 146097);
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  UtcTime u;
  u.day = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  u.month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  u.year = static_cast<int>(yoe + era * 400 + (u.month <= 2 ? 1 : 0));
  u.hour = static_cast<int>(sod / 3600);
  u.minute = static_cast<int>((sod % 3600) / 60);
  u.second = static_cast<int>(sod % 60);
  u.nanosecond = unix_ns - s * kNsPerSecond;
  return u;
}

int LeapSecondsAt(UnixTime t) {
  const std::int64_t unix_s = FloorDiv(ToNs(t), kNsPerSecond);
  int leap = 0;
  for (const LeapStep& step : kLeapSteps) {
    if (unix_s >= step.unix_s) leap = step.gps_minus_utc_s;
  }
  return leap;
}

GpsWeekTime GpsFrom(UnixTime t) {
  const std::int64_t gps_ns =
      ToNs(t) - kGpsEpochUnix_s * kNsPerSecond + LeapSecondsAt(t) * kNsPerSecond;
  GpsWeekTime g;
  g.week = static_cast<int>(FloorDiv(gps_ns, kSecondsPerWeek * kNsPerSecond));
  g.tow_ns = gps_ns - static_cast<std::int64_t>(g.week) * kSecondsPerWeek * kNsPerSecond;
  return g;
}

UnixTime UnixTimeFromGps(const GpsWeekTime& gps) {
  const std::int64_t gps_ns =
      static_cast<std::int64_t>(gps.week) * kSecondsPerWeek * kNsPerSecond + gps.tow_ns;
  // Leap seconds are looked up at the approximate UTC instant, then corrected once.
  const UnixTime approx = UnixTimeFromNs(gps_ns + kGpsEpochUnix_s * kNsPerSecond);
  const std::chrono::seconds first{LeapSecondsAt(approx)};
  return approx - std::chrono::seconds{LeapSecondsAt(approx - first)};
}

UnixTime ParseIsoUtc(const std::string& text) {
  UtcTime u;
  char frac[16] = {0};
  int consumed = 0;
  const int n = std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%n", &u.year, &u.month, &u.day,
                            &u.hour, &u.minute, &u.second, &consumed);
  if (n != 6)
    throw std::invalid_argument("not an ISO 8601 UTC time (YYYY-MM-DDThh:mm:ssZ): '" + text + "'");
  std::size_t pos = static_cast<std::size_t>(consumed);
  if (pos < text.size() && text[pos] == '.') {
    std::size_t k = 0;
    ++pos;
    while (pos < text.size() && text[pos] >= '0' && text[pos] <= '9') {
      if (k < 9) frac[k++] = text[pos];
      ++pos;
    }
    while (k < 9) frac[k++] = '0';
    u.nanosecond = std::stoll(frac);
  }
  if (pos >= text.size() || text[pos] != 'Z' || pos + 1 != text.size()) {
    throw std::invalid_argument("UTC time must end in 'Z': '" + text + "'");
  }
  // GPS time starts in 1980; the upper bound keeps nanoseconds since 1970 inside 64 bits
  if (u.year < 1980 || u.year > 2200 || u.month < 1 || u.month > 12 || u.day < 1 || u.day > 31 ||
      u.hour > 23 || u.minute > 59 || u.second > 59) {
    throw std::invalid_argument("UTC time out of range: '" + text + "'");
  }
  if (u.day > DaysInMonth(u.year, u.month)) {  // else 2027-02-29 would silently be 1 March
    throw std::invalid_argument(
        "no such date: month " + std::to_string(u.month) + " of " + std::to_string(u.year) +
        " has " + std::to_string(DaysInMonth(u.year, u.month)) + " days: '" + text + "'");
  }
  return UnixTimeFromUtc(u);
}

}  // namespace hil::gnss

#include "hil/firmware_emu/gnss/gps_time.h"

#include <gtest/gtest.h>

namespace hil::gnss {
namespace {

TEST(GpsTimeTest, KnownInstants) {
  // 2013-06-10T08:00:00Z: GPS week 1744, TOW 115216 s (Monday 08:00 + 16 leap seconds)
  const UnixTime utc = ParseIsoUtc("2013-06-10T08:00:00Z");
  EXPECT_EQ(ToNs(utc), 1370851200LL * 1000000000LL);
  const GpsWeekTime g = GpsFrom(utc);
  EXPECT_EQ(g.week, 1744);
  EXPECT_EQ(g.tow_ns, (86400LL + 8 * 3600 + 16) * 1000000000LL);
  EXPECT_EQ(UnixTimeFromGps(g), utc);
}

TEST(GpsTimeTest, LeapSecondsTable) {
  const auto at = [](std::int64_t unix_s) {
    return LeapSecondsAt(UnixTimeFromNs(unix_s * 1000000000LL));
  };
  EXPECT_EQ(at(315964800), 0);    // GPS epoch
  EXPECT_EQ(at(1341100799), 15);  // 2012-06-30T23:59:59Z
  EXPECT_EQ(at(1341100800), 16);  // 2012-07-01
  EXPECT_EQ(at(1800000000), 18);  // 2027
  EXPECT_EQ(LeapSecondsAt(UnixTimeFromNs(1341100800LL * 1000000000LL - 1)), 15);  // its last ns
}

TEST(GpsTimeTest, CalendarRoundTripAcrossMidnightAndLeapDay) {
  for (const char* s :
       {"2016-02-29T23:59:59.999Z", "2000-01-01T00:00:00Z", "2026-12-31T23:59:59Z"}) {
    const UnixTime t = ParseIsoUtc(s);
    const UtcTime u = UtcFrom(t);
    EXPECT_EQ(UnixTimeFromUtc(u), t) << s;
  }
  const UtcTime u = UtcFrom(ParseIsoUtc("2016-02-29T23:59:59.5Z") + Duration{500000000});
  EXPECT_EQ(u.month, 3);
  EXPECT_EQ(u.day, 1);
  EXPECT_EQ(u.hour, 0);
}

TEST(GpsTimeTest, RejectsMalformedTimes) {
  EXPECT_THROW(ParseIsoUtc("2013-06-10 08:00:00"), std::invalid_argument);
  EXPECT_THROW(ParseIsoUtc("2013-13-10T08:00:00Z"), std::invalid_argument);
  EXPECT_THROW(ParseIsoUtc("2013-06-10T08:00:00"), std::invalid_argument);
}

}  // namespace
}  // namespace hil::gnss

namespace hil::gnss {
namespace {

// Found by scenario_fuzz: a year before the GPS era overflowed the nanosecond arithmetic.
TEST(GpsTimeTest, RejectsYearsOutsideTheGpsEra) {
  EXPECT_THROW(ParseIsoUtc("0013-06-10T08:00:00Z"), std::invalid_argument);
  EXPECT_THROW(ParseIsoUtc("9999-06-10T08:00:00Z"), std::invalid_argument);
  EXPECT_NO_THROW(ParseIsoUtc("1980-01-06T00:00:00Z"));
}

}  // namespace
}  // namespace hil::gnss

namespace hil::gnss {
namespace {

// Issue 15.6: days past a month's end were accepted and ran shifted (2027-02-29 as 1 March).
TEST(GpsTimeTest, RejectsDaysPastTheEndOfTheMonth) {
  for (const char* s : {"2027-02-29T08:00:00Z", "2026-02-30T08:00:00Z", "2026-04-31T00:00:00Z",
                        "2026-06-31T00:00:00Z", "2100-02-29T00:00:00Z"})
    EXPECT_THROW(ParseIsoUtc(s), std::invalid_argument) << s;
  for (const char* s : {"2028-02-29T08:00:00Z", "2000-02-29T00:00:00Z", "2026-01-31T00:00:00Z",
                        "2026-12-31T23:59:59Z"})
    EXPECT_NO_THROW(ParseIsoUtc(s)) << s;
}

}  // namespace
}  // namespace hil::gnss

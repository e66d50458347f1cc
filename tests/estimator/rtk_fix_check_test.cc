// RtkFixCheck (rtk_fix_check.h): which fixes of a new RTK fixed episode are suspect.
#include "hil/estimator/rtk_fix_check.h"

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

constexpr int kFloat = 5, kFixed = 4;
constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
GpsTime At(double t_s) { return kT0 + Nanoseconds(static_cast<long long>(t_s * 1e9)); }

// float fixes at 10 Hz until 10 s, all accepted; returns the time of the last one
GpsTime FloatPeriod(RtkFixCheck& c) {
  for (int i = 0; i <= 100; ++i) EXPECT_FALSE(c.Observe(At(i * 0.1), kFloat, true, At(i * 0.1)));
  return At(10.0);
}

TEST(RtkFixCheck, NewFixRejectedByAnAidedFilterIsSuspectUntilAFixPasses) {
  RtkFixCheck c;
  const GpsTime last = FloatPeriod(c);
  EXPECT_TRUE(c.Observe(At(10.1), kFixed, false, last));
  EXPECT_TRUE(c.suspect_began());
  for (int i = 2; i < 300; ++i) EXPECT_TRUE(c.Observe(At(10.0 + i * 0.1), kFixed, false, last));
  EXPECT_FALSE(c.suspect_began());
  // the receiver re-fixes right: the raw fix passes the gate, the episode is over
  EXPECT_FALSE(c.Observe(At(40.0), kFixed, true, last));
  EXPECT_FALSE(c.suspect());
  EXPECT_FALSE(c.Observe(At(40.1), kFixed, false, At(40.0)));
  EXPECT_EQ(c.suspect_episodes(), 1U);
  EXPECT_EQ(c.suspect_fixes(), 299U);
}

TEST(RtkFixCheck, AFilterThatCoastedIsNotTrustedOverANewFix) {
  RtkFixCheck c;
  FloatPeriod(c);
  // the float fixes were rejected for 2 s: the filter is the one in doubt
  EXPECT_FALSE(c.Observe(At(10.1), kFixed, false, At(8.0)));
  EXPECT_FALSE(c.Observe(At(10.2), kFixed, false, At(8.0)));
  EXPECT_EQ(c.suspect_episodes(), 0U);
}

TEST(RtkFixCheck, AnEpisodeWhoseFirstFixPassedIsNeverSuspect) {
  RtkFixCheck c;
  FloatPeriod(c);
  EXPECT_FALSE(c.Observe(At(10.1), kFixed, true, At(10.0)));
  EXPECT_FALSE(c.Observe(At(10.2), kFixed, false, At(10.1)));
  // a float period and a new episode are judged afresh
  EXPECT_FALSE(c.Observe(At(10.3), kFloat, true, At(10.1)));
  EXPECT_TRUE(c.Observe(At(10.4), kFixed, false, At(10.3)));
}

TEST(RtkFixCheck, HeldLongerThanTheHoldItIsBelieved) {
  RtkFixCheckParams p;
  p.hold = Nanoseconds(5'000'000'000);
  RtkFixCheck c(p);
  const GpsTime last = FloatPeriod(c);
  EXPECT_TRUE(c.Observe(At(10.1), kFixed, false, last));
  for (int i = 2; i < 50; ++i) EXPECT_TRUE(c.Observe(At(10.0 + i * 0.1), kFixed, false, last));
  EXPECT_FALSE(c.Observe(At(15.1), kFixed, false, last));
  EXPECT_FALSE(c.Observe(At(15.2), kFixed, false, last));
}

TEST(RtkFixCheck, DisabledJudgesNothing) {
  RtkFixCheckParams p;
  p.enabled = false;
  RtkFixCheck c(p);
  const GpsTime last = FloatPeriod(c);
  EXPECT_FALSE(c.Observe(At(10.1), kFixed, false, last));
  EXPECT_EQ(c.suspect_episodes(), 0U);
}

}  // namespace
}  // namespace hil::estimator

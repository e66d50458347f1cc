// RtkFixCheck (rtk_fix_check.h): RTK fix episodes, and the suspect one's hold.
#include "hil/estimator/rtk_fix_check.h"

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

constexpr int kFloat = 5, kFixed = 4;
constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
GpsTime At(double t_s) { return kT0 + Nanoseconds(static_cast<long long>(t_s * 1e9)); }

// float fixes at 10 Hz until 10 s
void FloatPeriod(RtkFixCheck& c) {
  for (int i = 0; i <= 100; ++i) EXPECT_FALSE(c.BeginsEpisode(At(i * 0.1), kFloat));
}

TEST(RtkFixCheck, AnEpisodeBeginsWithAFixedSolutionAfterAnythingElseOrAGap) {
  RtkFixCheck c;
  FloatPeriod(c);
  EXPECT_TRUE(c.BeginsEpisode(At(10.1), kFixed));
  for (int i = 2; i < 30; ++i) EXPECT_FALSE(c.BeginsEpisode(At(10.0 + i * 0.1), kFixed));
  // 2 s without fixes (longer than trusted_within): a new episode
  EXPECT_TRUE(c.BeginsEpisode(At(15.0), kFixed));
  EXPECT_FALSE(c.BeginsEpisode(At(15.1), kFloat));
  EXPECT_TRUE(c.BeginsEpisode(At(15.2), kFixed));
}

TEST(RtkFixCheck, ASuspectEpisodeEndsWithTheQualityOrItsHold) {
  RtkFixCheckParams p;
  p.hold = Nanoseconds(5'000'000'000);
  RtkFixCheck c(p);
  FloatPeriod(c);
  ASSERT_TRUE(c.BeginsEpisode(At(10.1), kFixed));
  c.BeginSuspect(At(10.1));
  EXPECT_TRUE(c.suspect());
  EXPECT_FALSE(c.BeginsEpisode(At(10.2), kFixed));
  c.CountSuspectFix();
  EXPECT_FALSE(c.HoldOver(At(15.0)));
  EXPECT_TRUE(c.HoldOver(At(15.1)));
  EXPECT_TRUE(c.suspect());
  // the receiver drops to float: the suspicion is over
  EXPECT_FALSE(c.BeginsEpisode(At(15.2), kFloat));
  EXPECT_FALSE(c.suspect());
  EXPECT_EQ(c.suspect_episodes(), 1U);
  EXPECT_EQ(c.suspect_fixes(), 2U);
}

TEST(RtkFixCheck, TheFilterIsAidedWhenItAcceptedAFixJustBefore) {
  RtkFixCheck c;
  EXPECT_TRUE(c.FilterAided(At(10.1), At(10.0)));
  EXPECT_FALSE(c.FilterAided(At(10.1), At(8.0)));
  EXPECT_FALSE(c.FilterAided(At(10.1), std::nullopt));
}

TEST(RtkFixCheck, DisabledBeginsNoEpisode) {
  RtkFixCheckParams p;
  p.enabled = false;
  RtkFixCheck c(p);
  FloatPeriod(c);
  EXPECT_FALSE(c.BeginsEpisode(At(10.1), kFixed));
}

}  // namespace
}  // namespace hil::estimator

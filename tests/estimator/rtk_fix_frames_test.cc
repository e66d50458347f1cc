// RtkFixFrames (rtk_fix_frames.h): which RTK fix episodes agree, and when the filter moves.
#include "hil/estimator/rtk_fix_frames.h"

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

using Verdict = RtkFixFrames::Verdict;

// an episode's first fix offset_N_m from the filter, with a 2 cm σ per axis (fix and filter)
PositionInnovation FirstFix(double e, double n, double u) {
  PositionInnovation f;
  f.nu_m = Eigen::Vector3d(e, n, u);
  f.S_m2 = Eigen::Matrix3d::Identity() * 0.02 * 0.02;
  f.nis = f.nu_m.squaredNorm() / (0.02 * 0.02);
  f.valid = true;
  return f;
}

TEST(RtkFixFrames, AnEpisodeThatAgreesWithTheFilterIsInItsFrame) {
  RtkFixFrames f;
  EXPECT_EQ(f.Judge(FirstFix(0.03, -0.02, 0.04)).verdict, Verdict::kFilterFrame);  // NIS 7.25
  EXPECT_EQ(f.filter_frame_episodes(), 1);
  EXPECT_EQ(f.other_frames(), 0);
}

TEST(RtkFixFrames, TwoAgreeingEpisodesOutvoteTheOneTheFilterFollowed) {
  RtkFixFrames f;
  f.Judge(FirstFix(0, 0, 0));  // the filter followed this (wrong) episode
  // a disagreeing one: one against one, the filter keeps its frame, the episode is fused less
  // its offset
  const RtkFixFrames::Decision a = f.Judge(FirstFix(0.25, 0.05, 0.10));
  EXPECT_EQ(a.verdict, Verdict::kOtherFrame);
  EXPECT_TRUE(a.offset_N_m.isApprox(Eigen::Vector3d(0.25, 0.05, 0.10)));
  EXPECT_NEAR(a.var_m2.x(), 0.02 * 0.02, 1e-12);
  // a third agrees with it (within its σ): two against one, the filter moves by their offset,
  // the two measurements combined
  const RtkFixFrames::Decision b = f.Judge(FirstFix(0.27, 0.05, 0.10));
  EXPECT_EQ(b.verdict, Verdict::kSwitch);
  EXPECT_NEAR(b.offset_N_m.x(), 0.26, 1e-9);
  EXPECT_NEAR(b.var_m2.x(), 0.02 * 0.02 / 2, 1e-12);
  EXPECT_EQ(f.filter_frame_episodes(), 2);
  EXPECT_EQ(f.switches(), 1U);
  // the old frame is a hypothesis now, seen from the new one
  EXPECT_EQ(f.other_frames(), 1);
  EXPECT_EQ(f.Judge(FirstFix(0.005, 0, 0)).verdict, Verdict::kFilterFrame);
  const RtkFixFrames::Decision old = f.Judge(FirstFix(-0.26, -0.05, -0.10));
  EXPECT_EQ(old.verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.switches(), 1U);
}

TEST(RtkFixFrames, WrongEpisodesOfTheirOwnNeverOutvoteARightFilter) {
  RtkFixFrames f;
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(0.01, 0, 0));
  // wrong fixes: each off by an offset of its own
  EXPECT_EQ(f.Judge(FirstFix(0.3, 0, 0)).verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.Judge(FirstFix(0, -0.2, 0.1)).verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.Judge(FirstFix(-0.15, 0.1, 0)).verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.other_frames(), 3);
  EXPECT_EQ(f.switches(), 0U);
  // even two wrong ones in the same frame only tie with two right ones
  EXPECT_EQ(f.Judge(FirstFix(0.3, 0.01, 0)).verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.switches(), 0U);
}

TEST(RtkFixFrames, ATieGoesToTheFrameNearerTheFloatSolution) {
  RtkFixFrames f;
  // the first episode, 0.25 m from the float solution the filter held (σ 0.1 m): followed
  PositionInnovation first = FirstFix(-0.25, 0, 0);
  first.S_m2 = Eigen::Matrix3d::Identity() * 0.1 * 0.1;
  first.nis = 0.25 * 0.25 / (0.1 * 0.1);
  EXPECT_EQ(f.Judge(first).verdict, Verdict::kFilterFrame);
  // one episode against one: the second lies where the float solution was, the filter moves
  const RtkFixFrames::Decision d = f.Judge(FirstFix(0.25, 0, 0));
  EXPECT_EQ(d.verdict, Verdict::kSwitch);
  // one the float solution does not favour keeps the filter's frame
  RtkFixFrames g;
  g.Judge(first);
  EXPECT_EQ(g.Judge(FirstFix(-0.25, 0, 0)).verdict, Verdict::kOtherFrame);
}

TEST(RtkFixFrames, AFirstEpisodeAgainstAFilterThatSawNoneIsFollowed) {
  RtkFixFrames f;
  const RtkFixFrames::Decision d = f.Judge(FirstFix(0.4, 0, 0));
  EXPECT_EQ(d.verdict, Verdict::kSwitch);
  EXPECT_NEAR(d.offset_N_m.x(), 0.4, 1e-12);
}

TEST(RtkFixFrames, AnEpisodeHeldLongEnoughIsAdopted) {
  RtkFixFrames f;
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(0, 0.001, 0));
  EXPECT_EQ(f.Judge(FirstFix(0.2, 0, 0)).verdict, Verdict::kOtherFrame);
  EXPECT_NEAR(f.current_offset_N_m().x(), 0.2, 1e-12);
  const RtkFixFrames::Decision d = f.AdoptCurrent();
  EXPECT_EQ(d.verdict, Verdict::kSwitch);
  EXPECT_NEAR(d.offset_N_m.x(), 0.2, 1e-12);
  EXPECT_TRUE(f.current_offset_N_m().isZero());
  EXPECT_EQ(f.AdoptCurrent().verdict, Verdict::kFilterFrame);
}

TEST(RtkFixFrames, RestartForgetsTheOtherFrames) {
  RtkFixFrames f;
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(0.2, 0, 0));
  f.Restart();
  EXPECT_EQ(f.other_frames(), 0);
  EXPECT_EQ(f.filter_frame_episodes(), 1);
  EXPECT_EQ(f.Judge(FirstFix(0.2, 0, 0)).verdict, Verdict::kOtherFrame);
}

TEST(RtkFixFrames, ItKeepsAFixedNumberOfHypothesesTheMostSeenFirst) {
  RtkFixFrames f;
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(0, 0, 0));
  f.Judge(FirstFix(1.0, 0, 0));
  f.Judge(FirstFix(1.0, 0, 0));  // seen twice: kept
  for (int k = 1; k <= RtkFixFrames::kMaxOtherFrames + 2; ++k) f.Judge(FirstFix(0, 0.2 * k, 0));
  EXPECT_EQ(f.other_frames(), RtkFixFrames::kMaxOtherFrames);
  // the frame seen twice is still there: a third sighting moves the filter
  EXPECT_EQ(f.Judge(FirstFix(1.0, 0, 0)).verdict, Verdict::kOtherFrame);
  EXPECT_EQ(f.Judge(FirstFix(1.0, 0, 0)).verdict, Verdict::kSwitch);
}

}  // namespace
}  // namespace hil::estimator

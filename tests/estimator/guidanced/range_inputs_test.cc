// guidanced's RangeInputs: each Benewake frame's device time is its place in its stream (one
// 9-byte frame per period from the start), a solution gets the frames that have arrived by its
// time (measured, then 9 bytes at 115200 Bd: 0.78 ms on the wire), later frames wait for the next
// one, and the sets do not depend on how the bytes were read.
#include "range_inputs.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::guidanced {
namespace {

namespace est = hil::estimator;
using est::guidance::RangeSet;

constexpr std::int64_t kStartNs = 28'800'000'000'000LL;  // 08:00:00 UTC
constexpr std::int64_t kMs = 1'000'000;

est::GpsTime At(std::int64_t ms_after_start) {
  return est::GpsTimeFromNs(kStartNs + ms_after_start * kMs);
}
// A solution 1 ms after a whole number of periods: the frame measured then has arrived.
est::GpsTime Sol(std::int64_t ms_after_start) { return At(ms_after_start) + est::Nanoseconds{kMs}; }

// A TF-Luna data frame: `cm` centimetres, amplitude 1000, 40 °C, with its checksum.
std::string Frame(unsigned cm) {
  std::string f{
      '\x59', '\x59', static_cast<char>(cm & 0xFF), static_cast<char>(cm >> 8), '\xE8', '\x03',
      '\x40', '\x09'};
  unsigned sum = 0;
  for (const char c : f) sum += static_cast<unsigned char>(c);
  f.push_back(static_cast<char>(sum & 0xFF));
  return f;
}

// Frames first..last of unit k: unit k's frame n reads 100·(k+1) + n cm.
std::string Frames(std::size_t k, int first, int last) {
  std::string s;
  for (int n = first; n <= last; ++n) s += Frame(static_cast<unsigned>(100 * (k + 1) + n));
  return s;
}

RangeInputs Configured(std::optional<est::GpsTime> start = est::GpsTimeFromNs(kStartNs)) {
  RangeInputs in;
  in.Configure(false, 100.0, 115200, start);
  return in;
}

std::vector<RangeSet> Drain(RangeInputs& in, est::GpsTime t) {
  std::vector<RangeSet> sets;
  in.Drain(t, [&](const RangeSet& r) { sets.push_back(r); });
  return sets;
}

TEST(RangeInputsTest, FramesAreTimedByTheirPlaceInTheStream) {
  // GIVEN 25 frames of each unit, read in one piece
  RangeInputs in = Configured();
  for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) in.Feed(k, Frames(k, 0, 24));
  // WHEN the solution of t = 101 ms drains: frames 0..9 (10..100 ms), the rest stays queued
  const std::vector<RangeSet> a = Drain(in, Sol(100));
  ASSERT_EQ(a.size(), 10u);
  for (int n = 0; n < 10; ++n) {
    EXPECT_EQ(a[n].t, At(10 * (n + 1))) << n;
    EXPECT_NEAR(a[n].right_front_m, (100 + n) / 100.0, 1e-12);
    EXPECT_NEAR(a[n].right_rear_m, (200 + n) / 100.0, 1e-12);
    EXPECT_NEAR(a[n].left_front_m, (300 + n) / 100.0, 1e-12);
    EXPECT_NEAR(a[n].left_rear_m, (400 + n) / 100.0, 1e-12);
    EXPECT_TRUE(a[n].right_front_ok && a[n].right_rear_ok && a[n].left_front_ok &&
                a[n].left_rear_ok);
  }
  // THEN the next solutions get 110..200 ms and the last five
  const std::vector<RangeSet> b = Drain(in, Sol(200));
  ASSERT_EQ(b.size(), 10u);
  EXPECT_EQ(b.front().t, At(110));
  EXPECT_NEAR(b.front().right_front_m, 1.10, 1e-12);
  EXPECT_EQ(Drain(in, Sol(300)).size(), 5u);
  EXPECT_TRUE(Drain(in, Sol(400)).empty());
  EXPECT_EQ(in.overflows(), 0u);
}

TEST(RangeInputsTest, AFrameCountsOnceItsLastByteHasArrived) {
  RangeInputs in = Configured();
  for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) in.Feed(k, Frames(k, 0, 10));
  // the frame measured at 100 ms is on the wire until 100.78125 ms (90 bits at 115200 Bd)
  EXPECT_EQ(Drain(in, At(100)).size(), 9u);
  EXPECT_TRUE(Drain(in, At(100) + est::Nanoseconds{781'249}).empty());
  const std::vector<RangeSet> last = Drain(in, At(100) + est::Nanoseconds{781'250});
  ASSERT_EQ(last.size(), 1u);
  EXPECT_EQ(last[0].t, At(100));
}

// The property guidanced needs in a lockstep run: whether a solution's reader found the port
// holding a few frames of after its time or none, the solutions get the same sets.
TEST(RangeInputsTest, SetsDoNotDependOnWhenThePortsWereRead) {
  RangeInputs early = Configured(), late = Configured();
  std::vector<RangeSet> from_early, from_late;
  const auto append = [](std::vector<RangeSet>& to, const std::vector<RangeSet>& more) {
    to.insert(to.end(), more.begin(), more.end());
  };
  // `early` reads exactly up to each solution's time; `late` has read 7 frames further, in
  // pieces that split frames
  for (int sol = 1; sol <= 4; ++sol) {
    for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) {
      early.Feed(k, Frames(k, 10 * (sol - 1), 10 * sol - 1));
      const std::size_t from = sol == 1 ? 0 : 9 * (10 * (sol - 1) + 7);
      const std::size_t to = 9 * (10 * sol + 7);
      const std::string all = Frames(k, 0, 10 * sol + 6);
      late.Feed(k, all.substr(from, (to - from) / 2));
      late.Feed(k, all.substr(from + (to - from) / 2, to - from - (to - from) / 2));
    }
    append(from_early, Drain(early, Sol(100 * sol)));
    append(from_late, Drain(late, Sol(100 * sol)));
  }
  ASSERT_EQ(from_early.size(), 40u);
  ASSERT_EQ(from_late.size(), 40u);
  for (std::size_t i = 0; i < 40; ++i) {
    EXPECT_EQ(from_early[i].t, from_late[i].t) << i;
    EXPECT_EQ(from_early[i].right_front_m, from_late[i].right_front_m) << i;
    EXPECT_EQ(from_early[i].left_rear_m, from_late[i].left_rear_m) << i;
  }
}

TEST(RangeInputsTest, PairsTheOtherUnitsByFrameNumber) {
  // GIVEN the left-rear unit two frames behind the others, and a garbage byte in the right-rear
  // stream (the frames after it keep their numbers: the nearest whole frame)
  RangeInputs in = Configured();
  in.Feed(0, Frames(0, 0, 9));
  in.Feed(1, Frames(1, 0, 3) + "\x13" + Frames(1, 4, 9));
  in.Feed(2, Frames(2, 0, 9));
  in.Feed(3, Frames(3, 0, 7));
  const std::vector<RangeSet> sets = Drain(in, Sol(100));
  ASSERT_EQ(sets.size(), 10u);
  EXPECT_NEAR(sets[6].right_rear_m, 2.06, 1e-12);
  EXPECT_NEAR(sets[6].left_rear_m, 4.06, 1e-12);
  // frames 8 and 9 of the left rear are not there yet: its newest, frame 7
  EXPECT_NEAR(sets[9].left_rear_m, 4.07, 1e-12);
  EXPECT_NEAR(sets[9].left_front_m, 3.09, 1e-12);
  EXPECT_EQ(in.bad_bytes(), 1u);
}

TEST(RangeInputsTest, DropsStaleFramesAndAnchorsWithoutAStart) {
  // GIVEN one second of frames before the first solution (navd aligning)
  RangeInputs in = Configured();
  for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) in.Feed(k, Frames(k, 0, 99));
  // THEN that solution gets only the frames measured in the last kMaxAge: 510..1000 ms
  const std::vector<RangeSet> sets = Drain(in, Sol(1000));
  ASSERT_EQ(sets.size(), 50u);
  EXPECT_EQ(sets.front().t, At(510));
  EXPECT_NEAR(sets.front().left_front_m, 3.50, 1e-12);

  // GIVEN no start: the newest frame read at the first solution is of that solution's time
  RangeInputs anchored = Configured(std::nullopt);
  for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) anchored.Feed(k, Frames(k, 0, 4));
  const est::Nanoseconds wire{781'250};
  const std::vector<RangeSet> first = Drain(anchored, At(1000) + wire);
  ASSERT_EQ(first.size(), 5u);
  EXPECT_EQ(first.back().t, At(1000));
  EXPECT_EQ(first.front().t, At(960));
  for (std::size_t k = 0; k < RangeInputs::kUnits; ++k) anchored.Feed(k, Frames(k, 5, 14));
  const std::vector<RangeSet> next = Drain(anchored, At(1050) + wire);
  ASSERT_EQ(next.size(), 5u);
  EXPECT_EQ(next.back().t, At(1050));
  EXPECT_NEAR(next.back().right_front_m, 1.09, 1e-12);
}

}  // namespace
}  // namespace hil::guidanced

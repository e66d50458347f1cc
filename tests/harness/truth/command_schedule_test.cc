// The closed loop's commands in bounded memory (issue 40, minor: hil's memory per emulated hour):
// every command of the run was kept in the truth integrator's schedule, 24 B each at the command
// grid's 100 Hz; the oldest now go to a temporary file and are read back in order.
#include "hil/truth/command_schedule.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

namespace hil::truth {
namespace {

// What the schedule must answer: the latest entry at or before t_s (none before the first).
const CommandSchedule::Entry* Expected(const std::vector<CommandSchedule::Entry>& all, double t_s) {
  const auto it =
      std::upper_bound(all.begin(), all.end(), t_s,
                       [](double x, const CommandSchedule::Entry& e) { return x < e.t_s; });
  return it == all.begin() ? nullptr : &*std::prev(it);
}

void ExpectAt(CommandSchedule& schedule, const std::vector<CommandSchedule::Entry>& all,
              double t_s) {
  const CommandSchedule::Entry* got = schedule.At(t_s);
  const CommandSchedule::Entry* want = Expected(all, t_s);
  ASSERT_EQ(got == nullptr, want == nullptr) << "t = " << t_s;
  if (!want) return;
  EXPECT_EQ(got->t_s, want->t_s) << "t = " << t_s;
  EXPECT_EQ(got->speed_mps, want->speed_mps) << "t = " << t_s;
  EXPECT_EQ(got->steer_or_yaw_rate, want->steer_or_yaw_rate) << "t = " << t_s;
}

TEST(CommandScheduleTest, TenEmulatedHoursOfCommandsHoldNoMoreThanItsMemoryEntries) {
  // GIVEN ten emulated hours of 100 Hz commands (3.6 million), added as a run reads them
  CommandSchedule schedule(1000);
  std::vector<CommandSchedule::Entry> all;
  std::size_t most = 0;
  for (long k = 0; k < 3'600'000; ++k) {
    const CommandSchedule::Entry e{0.01 * static_cast<double>(k) + 0.005,
                                   1.0 + 1e-6 * static_cast<double>(k),
                                   0.001 * static_cast<double>(k % 100)};
    schedule.Add(e);
    if (k % 1000 == 0) all.push_back(e);  // a sparse reference, to keep the test's own memory low
    if (k % 997 == 0) (void)schedule.At(e.t_s);
    most = std::max(most, schedule.in_memory());
  }
  // THEN it never held more than its memory entries, and holds them all
  EXPECT_LE(most, 1000u);
  EXPECT_EQ(schedule.size(), 3'600'000u);
  // AND a restart from t = 0 reads them back in order, from the file and from memory
  schedule.Rewind();
  for (const CommandSchedule::Entry& e : all) {
    const CommandSchedule::Entry* got = schedule.At(e.t_s);
    ASSERT_NE(got, nullptr);
    EXPECT_EQ(got->t_s, e.t_s);
    EXPECT_EQ(got->speed_mps, e.speed_mps);
  }
}

TEST(CommandScheduleTest, AnswersAsTheWholeScheduleWouldAcrossRewindsAndTies) {
  // GIVEN 50 commands, two at each instant (the later wins), 8 held in memory
  CommandSchedule schedule(8);
  std::vector<CommandSchedule::Entry> all;
  for (int k = 0; k < 50; ++k) {
    all.push_back({0.1 * (k / 2), static_cast<double>(k), -static_cast<double>(k)});
    schedule.Add(all.back());
  }
  // WHEN asked forwards, backwards (a restart) and between and before the instants
  for (const double t : {-1.0, 0.0, 0.05, 0.1, 1.0, 2.45, 0.3, 0.3, 2.4, 9.0, 0.0})
    ExpectAt(schedule, all, t);
  // THEN (above) every answer is the whole schedule's
  EXPECT_LE(schedule.in_memory(), 8u);
}

}  // namespace
}  // namespace hil::truth

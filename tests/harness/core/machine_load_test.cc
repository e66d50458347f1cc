// The machine figures of a real-time run's schedule_error.json (machine_load.h).
#include "hil/harness/core/machine_load.h"

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

TEST(MachineLoadTest, ParsesTheAggregateCpuLineAndSharesTheTicksBetweenTwoReadings) {
  const auto a = ParseProcStat(
      "cpu  100 20 30 400 5 0 5 40 0 0\ncpu0 50 10 15 200 2 0 3 20 0 0\nintr 1 2 3\n");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->user, 100u);
  EXPECT_EQ(a->nice, 20u);
  EXPECT_EQ(a->idle, 400u);
  EXPECT_EQ(a->steal, 40u);
  EXPECT_EQ(a->total(), 600u);
  const auto b = ParseProcStat("cpu  160 20 50 500 5 0 5 60 0 0\n");
  ASSERT_TRUE(b);
  // 200 ticks: 80 busy (user 60, system 20), 100 idle, 20 stolen
  const CpuShares s = SharesBetween(*a, *b);
  EXPECT_EQ(s.ticks, 200u);
  EXPECT_DOUBLE_EQ(s.busy_pct, 40.0);
  EXPECT_DOUBLE_EQ(s.idle_pct, 50.0);
  EXPECT_DOUBLE_EQ(s.steal_pct, 10.0);
}

TEST(MachineLoadTest, AnOldKernelsShortLineAndAMissingLine) {
  const auto old = ParseProcStat("cpu  1 2 3 4\n");
  ASSERT_TRUE(old);
  EXPECT_EQ(old->steal, 0u);
  EXPECT_EQ(old->total(), 10u);
  EXPECT_FALSE(ParseProcStat("cpu0 1 2 3 4\n"));
  EXPECT_FALSE(ParseProcStat(""));
  EXPECT_EQ(SharesBetween(*old, *old).ticks, 0u);
}

TEST(MachineLoadTest, ThisMachinesFigures) {
  const MachineFigures m = ReadMachineFigures();
  EXPECT_GE(m.cpus_online, 1);
  EXPECT_GE(m.load_1m, 0.0);
  EXPECT_FALSE(m.kernel.empty());
  EXPECT_TRUE(ReadCpuTicks());
}

}  // namespace
}  // namespace hil::harness

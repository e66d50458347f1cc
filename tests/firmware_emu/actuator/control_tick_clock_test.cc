#include "hil/firmware_emu/actuator/control_tick_clock.h"

#include <chrono>
#include <vector>

#include <gtest/gtest.h>

namespace hil::actuator {
namespace {

using std::chrono::milliseconds;

ControlTickTiming Timing() {
  return {milliseconds(10), milliseconds(100), milliseconds(300), Time{milliseconds(500)}};
}

TEST(ControlTickClockTest, TicksOncePerControlPeriodFromOnePeriodAfterTheStart) {
  ControlTickClock c(Timing());
  std::vector<Time> due;
  for (int ms = 0; ms <= 300; ms += 10) {
    const Time t{milliseconds(ms)};
    if (c.TickDue(t)) due.push_back(t);
  }
  EXPECT_EQ(due, (std::vector<Time>{Time{milliseconds(100)}, Time{milliseconds(200)},
                                    Time{milliseconds(300)}}));
}

TEST(ControlTickClockTest, ACommandIsMissingOnlyOnceDueAndWhenTheLatestIsOlderThanTheTimeout) {
  ControlTickClock c(Timing());
  ControlTickCounters n;
  EXPECT_FALSE(c.CountTick(Time{milliseconds(400)}, n)) << "before first_command_due";
  EXPECT_TRUE(c.CountTick(Time{milliseconds(500)}, n)) << "none yet";
  EXPECT_EQ(n.first_missing, Time{milliseconds(500)});
  n.last_command = Time{milliseconds(550)};
  EXPECT_FALSE(c.CountTick(Time{milliseconds(800)}, n)) << "250 ms old";
  EXPECT_FALSE(c.CountTick(Time{milliseconds(850)}, n)) << "exactly the timeout";
  EXPECT_TRUE(c.CountTick(Time{milliseconds(900)}, n));
  EXPECT_TRUE(c.CountTick(Time{milliseconds(1000)}, n));
  EXPECT_EQ(n.ticks, 6u);
  EXPECT_EQ(n.missing_commands, 3u);
  EXPECT_EQ(n.first_missing, Time{milliseconds(900)}) << "the first of the latest run";
}

TEST(ControlTickClockTest, TheHeldCommandActsFromTheNextGridInstantAndIsTakenOnce) {
  ControlTickClock c(Timing());
  c.Hold(Time{}, 1.0, 0.1);
  EXPECT_EQ(c.next_event_time(), Time{milliseconds(10)});
  auto cmd = c.TakeVehicleCommand();
  ASSERT_TRUE(cmd.has_value());
  EXPECT_EQ(cmd->t, Time{}) << "the first acts from the start";
  EXPECT_FALSE(c.TakeVehicleCommand().has_value());
  c.Hold(Time{milliseconds(10)}, 2.0, -0.2);
  cmd = c.TakeVehicleCommand();
  ASSERT_TRUE(cmd.has_value());
  EXPECT_EQ(cmd->t, Time{milliseconds(20)});
  EXPECT_EQ(cmd->speed_mps, 2.0);
  EXPECT_EQ(cmd->steer_or_yaw_rate, -0.2);
  EXPECT_EQ(c.next_event_time(), Time{milliseconds(20)});
}

}  // namespace
}  // namespace hil::actuator

// The pacers' own arithmetic (engine/pacer.h), without racing the wall clock: the wall-clock
// pacer's speed factor (when the event thread wakes, what emulated time host bytes arrive at) and
// lockstep's lateness accounting are computed from given wall instants.
#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>

#include <gtest/gtest.h>

#include "hil/harness/engine/device_io.h"
#include "hil/harness/engine/lockstep_pacer.h"
#include "hil/harness/engine/virtual_pacer.h"
#include "hil/harness/engine/wall_clock_pacer.h"

namespace hil::harness {
namespace {

constexpr Duration kS = std::chrono::seconds(1);
constexpr Duration kMs = std::chrono::milliseconds(1);

Time At(double s) { return TimeFromSeconds(s); }
WallTime Wall(Duration since_boot) { return WallTime{since_boot}; }

TEST(WallClockPacerTest, ScaledModeWakesAtTheEventsWallTimeDividedByTheSpeedMinusTheLead) {
  const WallClockPacer pacer{link::RealtimePacer(2.0)};  // scaled: twice real time
  const WallTime start = pacer.wall_clock()->WallTimeOf(Time{});
  // emulated 10 s is wall 5 s after the start; the event is computed kEventLead before
  const WallTime due = start + 5 * kS - WallClockPacer::kEventLead;
  // far from it: the thread looks for host bytes again after kHostPollPeriod
  EXPECT_EQ(pacer.Wake(At(10), At(20), start), start + WallClockPacer::kHostPollPeriod);
  // closer than one poll period: it wakes when the event is due
  EXPECT_EQ(pacer.Wake(At(10), At(20), due - kMs / 2), due);
  // due (or late): computed now
  EXPECT_EQ(pacer.Wake(At(10), At(20), due), std::nullopt);
  EXPECT_EQ(pacer.Wake(At(10), At(20), due + kS), std::nullopt);
  // at real time (factor 1) the same event lies 10 s after the start: 4 s before it, it waits
  const WallClockPacer realtime{link::RealtimePacer(1.0)};
  const WallTime start_1 = realtime.wall_clock()->WallTimeOf(Time{});
  EXPECT_NE(realtime.Wake(At(10), At(20), start_1 + 6 * kS), std::nullopt);
  EXPECT_EQ(realtime.Wake(At(10), At(20), start_1 + 10 * kS), std::nullopt);
}

TEST(WallClockPacerTest, AnEventAfterTheEndIsNotWaitedFor) {
  const WallClockPacer pacer{link::RealtimePacer(1.0)};
  const WallTime start = pacer.wall_clock()->WallTimeOf(Time{});
  EXPECT_EQ(pacer.Wake(At(30), At(20), start), std::nullopt);
}

TEST(WallClockPacerTest, HostBytesArriveAtTheEmulatedTimeOfTheirWallInstantNotBeforeTheLastEvent) {
  const WallClockPacer pacer{link::RealtimePacer(4.0)};
  const WallTime start = pacer.wall_clock()->WallTimeOf(Time{});
  // wall 1 s after the start is emulated 4 s at four times real time
  EXPECT_EQ(pacer.ArrivalTime(start + kS, At(3)), At(4));
  // the devices computed an event at 5 s already: the bytes count from it
  EXPECT_EQ(pacer.ArrivalTime(start + kS, At(5)), At(5));
  EXPECT_FALSE(pacer.host_bytes_virtual());
  EXPECT_EQ(pacer.bus_stamp_clock(), pacer.wall_clock());
  EXPECT_EQ(pacer.stepping(), Stepping::kFreeRunning);
}

TEST(PaceLatenessTest, CountsEveryActionAndOnlyThoseMoreThanAMillisecondLate) {
  PaceLateness p;
  EXPECT_TRUE(p.Note(Wall(10 * kMs), Wall(9 * kMs)));  // early: it waits, nothing late
  EXPECT_EQ(p.actions, 1u);
  EXPECT_EQ(p.late, 0u);
  EXPECT_EQ(p.max_late, Duration::zero());
  EXPECT_FALSE(p.Note(Wall(10 * kMs), Wall(10 * kMs + kMs / 2)));  // 0.5 ms: served, not late
  EXPECT_EQ(p.late, 0u);
  EXPECT_EQ(p.max_late, kMs / 2);
  EXPECT_FALSE(p.Note(Wall(20 * kMs), Wall(23 * kMs)));  // 3 ms late
  EXPECT_FALSE(p.Note(Wall(30 * kMs), Wall(31 * kMs)));  // exactly the limit: not late
  EXPECT_EQ(p.actions, 4u);
  EXPECT_EQ(p.late, 1u);
  EXPECT_EQ(p.max_late, 3 * kMs);
}

TEST(LockstepPacerTest, HoldsTheStepsFirstActionToTheWallClockAndCountsItsLateness) {
  LockstepPacer pacer{link::RealtimePacer(1.0)};
  EXPECT_EQ(pacer.stepping(), Stepping::kLockstep);
  EXPECT_NE(pacer.wall_clock(), nullptr);
  EXPECT_EQ(pacer.bus_stamp_clock(), nullptr);  // frames take the engine's emulated time
  EXPECT_TRUE(pacer.host_bytes_virtual());
  std::this_thread::sleep_for(std::chrono::milliseconds(3));  // at least 3 ms past t = 0
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  DeviceIo io(EngineDevices{devices, endpoints}, pacer, false);
  DeviceOutput out;
  // the event lies an hour ahead, but a host turn at t = 0 comes first: that is what is paced
  EXPECT_FALSE(pacer.Await(StepTimes{At(3600), At(7200), Time{}}, io, out));
  EXPECT_EQ(pacer.lateness().actions, 1u);
  EXPECT_EQ(pacer.lateness().late, 1u);
  EXPECT_GE(pacer.lateness().max_late, 3 * kMs);
}

TEST(VirtualPacerTest, RunsFreeOfTheWallClock) {
  VirtualPacer pacer;
  EXPECT_EQ(pacer.stepping(), Stepping::kVirtual);
  EXPECT_EQ(pacer.wall_clock(), nullptr);
  EXPECT_EQ(pacer.HostBytesTime(At(7), At(9)), At(7));  // the turn's time, whatever the last event
  EXPECT_EQ(pacer.BusTime(At(9)), At(9));
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  DeviceIo io(EngineDevices{devices, endpoints}, pacer, false);
  DeviceOutput out;
  EXPECT_FALSE(pacer.Await(StepTimes{At(3600), At(7200), At(3600)}, io, out));  // no wait
  EXPECT_EQ(pacer.lateness().actions, 0u);
}

TEST(SteppingTest, NamesAsTheReportWritesThem) {
  EXPECT_STREQ(SteppingName(Stepping::kVirtual), "virtual");
  EXPECT_STREQ(SteppingName(Stepping::kFreeRunning), "free_running");
  EXPECT_STREQ(SteppingName(Stepping::kLockstep), "lockstep");
}

}  // namespace
}  // namespace hil::harness

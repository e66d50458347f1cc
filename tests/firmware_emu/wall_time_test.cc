#include "hil/firmware_emu/wall_time.h"

#include <chrono>
#include <cstdint>
#include <thread>
#include <type_traits>

#include <gtest/gtest.h>

namespace hil {
namespace {

// Whether two instants can be subtracted or compared: only instants of one clock can.
template <typename A, typename B>
concept Subtractable = requires(A a, B b) {
  a - b;
};
template <typename A, typename B>
concept Comparable = requires(A a, B b) {
  a < b;
};

TEST(WallTimeTest, InstantsOfTheWallAndTheEmulatedClockDoNotMix) {
  static_assert(Subtractable<WallTime, WallTime>);
  static_assert(Subtractable<Time, Time>);
  static_assert(!Subtractable<WallTime, Time>);
  static_assert(!Subtractable<Time, WallTime>);
  static_assert(!Comparable<WallTime, Time>);
  // and neither converts from a bare count of nanoseconds
  static_assert(!std::is_convertible_v<std::int64_t, WallTime>);
  // their differences are both Duration, as in <chrono>: a pacer scales one into the other
  static_assert(std::is_same_v<decltype(WallTime{} - WallTime{}), Duration>);
  static_assert(std::is_same_v<decltype(Time{} - Time{}), Duration>);
}

TEST(WallTimeTest, NowIsClockMonotonicInNanoseconds) {
  const WallTime a = WallNow();
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const WallTime b = WallNow();
  EXPECT_GE(b - a, std::chrono::milliseconds(2));
  EXPECT_EQ(ToNs(WallTimeFromNs(1234)), 1234);
  // the same instant on steady_clock (what sleep_until and wait_until take)
  const auto steady_before = std::chrono::steady_clock::now();
  const WallTime wall = WallNow();
  const auto steady_after = std::chrono::steady_clock::now();
  EXPECT_LE(steady_before, ToSteady(wall));
  EXPECT_LE(ToSteady(wall), steady_after);
}

}  // namespace
}  // namespace hil

#include "hil/firmware_emu/unix_time.h"

#include <chrono>
#include <cstdint>
#include <ctime>
#include <type_traits>

#include <gtest/gtest.h>

#include "hil/firmware_emu/wall_time.h"

namespace hil {
namespace {

template <typename A, typename B>
concept Subtractable = requires(A a, B b) {
  a - b;
};
template <typename A, typename B>
concept Comparable = requires(A a, B b) {
  a < b;
};

TEST(UnixTimeTest, UtcDoesNotMixWithTheWallOrTheEmulatedClock) {
  static_assert(Subtractable<UnixTime, UnixTime>);
  static_assert(!Subtractable<UnixTime, WallTime>);
  static_assert(!Subtractable<UnixTime, Time>);
  static_assert(!Comparable<UnixTime, WallTime>);
  static_assert(!Comparable<UnixTime, Time>);
  static_assert(!std::is_convertible_v<std::int64_t, UnixTime>);
  // emulated t maps onto UTC through a Duration: start + (t - Time{})
  static_assert(std::is_same_v<decltype(UnixTime{} + (Time{} - Time{})), UnixTime>);
}

TEST(UnixTimeTest, NowIsClockRealtimeInNanosecondsSinceTheUnixEpoch) {
  const std::time_t before_s = std::time(nullptr);
  const UnixTime now = UnixClock::now();
  const std::time_t after_s = std::time(nullptr);
  EXPECT_GE(ToNs(now) / 1000000000LL, static_cast<std::int64_t>(before_s));
  EXPECT_LE(ToNs(now) / 1000000000LL, static_cast<std::int64_t>(after_s));
  EXPECT_EQ(ToNs(UnixTimeFromNs(1370851200000000000LL)), 1370851200000000000LL);
}

}  // namespace
}  // namespace hil

// The J1939 encoders against the example frames of vectors/can/README.md and the reference's
// Honeywell/derived examples (can_and_transports.md §7).
#include "hil/firmware_emu/mcu/j1939_imu.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

namespace hil::mcu {
namespace {

std::string Candump(const CanFrame& f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%08X#", f.id);
  std::string s = buf;
  for (int i = 0; i < f.len; ++i) {
    std::snprintf(buf, sizeof buf, "%02X", f.data[i]);
    s += buf;
  }
  return s;
}

constexpr double kDeg = std::numbers::pi / 180.0;
const J1939Address kAddr{3, 0xE2};
const FiguresOfMerit kOk{0, 0, 0};

TEST(J1939ImuTest, IdentifiersFollowPrioPgnSa) {
  EXPECT_EQ(J1939Id(kAddr, kPgnAri), 0x0CF02AE2u);
  EXPECT_EQ(J1939Id(kAddr, kPgnAccs), 0x0CF02DE2u);
  EXPECT_EQ(J1939Id(kAddr, kPgnSsi2), 0x0CF029E2u);
  EXPECT_EQ(J1939Id(kAddr, kPgnHilTimePulse), 0x0CFF50E2u);
}

TEST(J1939ImuTest, AriExample) {
  EXPECT_EQ(Candump(EncodeAri(Time{}, kAddr, {0, 0, 10 * kDeg}, kOk, 0.001)),
            "0CF02AE2#007D007D0082C002");
}

TEST(J1939ImuTest, AriSignsPitchNoseUpIsMinusWy) {
  const CanFrame f = EncodeAri(Time{}, kAddr, {1 * kDeg, -2 * kDeg, 0}, kOk, 0.0);
  const int pitch_raw = f.data[0] | (f.data[1] << 8), roll_raw = f.data[2] | (f.data[3] << 8);
  EXPECT_EQ(pitch_raw, 32000 + 256);  // +2 °/s
  EXPECT_EQ(roll_raw, 32000 + 128);   // +1 °/s
}

TEST(J1939ImuTest, AccsExampleMatchesTheDerivedReferenceFrame) {
  EXPECT_EQ(Candump(EncodeAccs(Time{}, kAddr, {0, 0, 9.80665}, kOk, 0.001)),
            "0CF02DE2#007D007DD580C002");
  // the reference's frame with latency byte 0x0A and FoM bits as zero except the reserved pair
  const CanFrame f = EncodeAccs(Time{}, kAddr, {0, 0, 9.80665}, kOk, 0.005);
  EXPECT_EQ(f.data[7], 0x0A);
}

TEST(J1939ImuTest, Ssi2Example) {
  EXPECT_EQ(Candump(EncodeSsi2(Time{}, kAddr, {0, 0, 9.80665}, 0, 0, 0.001)),
            "0CF029E2#00007D00007D3302");
}

TEST(J1939ImuTest, Ssi2PitchNoseUpAndRollRightDownArePositive) {
  const double g = 9.80665, a = 10 * kDeg;
  const Eigen::Vector2d pr = PitchRollDegFromSpecificForce({g * std::sin(a), 0, g * std::cos(a)});
  EXPECT_NEAR(pr[0], 10.0, 1e-12);
  const Eigen::Vector2d rr = PitchRollDegFromSpecificForce({0, g * std::sin(a), g * std::cos(a)});
  EXPECT_NEAR(rr[1], 10.0, 1e-12);
}

TEST(J1939ImuTest, TimePulseExample) {
  EXPECT_EQ(Candump(EncodeHilTimePulse(Time{}, kAddr, 1000000, true, 86400, 1744)),
            "0CFF50E2#40420F008051016D");
  const CanFrame unknown = EncodeHilTimePulse(Time{}, kAddr, 1, false, 86400, 1744);
  EXPECT_EQ(unknown.data[4], 0xFF);
  EXPECT_EQ(unknown.data[5], 0xFF);
  EXPECT_EQ(unknown.data[6] & 0x0F, 0x0F);
}

TEST(J1939ImuTest, OutOfRangeValuesClampToTheValidRange) {
  const CanFrame f = EncodeAccs(Time{}, kAddr, {1000, -1000, 0}, kOk, 0.0);
  EXPECT_EQ(f.data[0] | (f.data[1] << 8), 0);       // lateral f_y = −1000 → min
  EXPECT_EQ(f.data[2] | (f.data[3] << 8), 0xFAFF);  // longitudinal f_x = +1000 → max
}

}  // namespace
}  // namespace hil::mcu

// Byte-exact checks of the MCU frame encoder against the worked examples of
// vectors/mcu/mcu_frame_protocol.md §7 and the CRC's standard check value.
#include "hil/firmware_emu/mcu/mcu_frame.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hex_bytes.h"

namespace hil::mcu {
namespace {

std::string Hex(const std::string& bytes) {
  return hil::test::HexBytes(bytes, {.upper = true, .sep = " "});
}

TEST(McuFrameTest, CrcMatchesTheCcittFalseCheckValue) {
  const std::string s = "123456789";
  const std::vector<std::uint8_t> b(s.begin(), s.end());
  EXPECT_EQ(Crc16CcittFalse(b), 0x29B1);
}

TEST(McuFrameTest, ImuSampleMatchesTheSpecExample) {
  ImuSamplePayload p;
  p.accel = {3, -5, 256};
  p.gyro = {-2, 1, -16};
  EXPECT_EQ(Hex(EncodeImuSample(0x0102, 0x00BC614E, p)),
            "A5 5A 01 01 0C 02 01 4E 61 BC 00 03 00 FB FF 00 01 FE FF 01 00 F0 FF A4 70");
}

TEST(McuFrameTest, TimePulseMatchesTheSpecExample) {
  TimePulsePayload p{1744, 86400000, true};
  EXPECT_EQ(Hex(EncodeTimePulse(7, 1000000, p)),
            "A5 5A 01 03 07 07 00 40 42 0F 00 D0 06 00 5C 26 05 01 20 C6");
}

TEST(McuFrameTest, MagSampleMatchesTheSpecExample) {
  MagSamplePayload p;
  p.mag = {300, -50, -600};
  EXPECT_EQ(Hex(EncodeMagSample(8, 1050000, p)),
            "A5 5A 01 02 06 08 00 90 05 10 00 2C 01 CE FF A8 FD A6 58");
}

TEST(McuFrameTest, StatusHasItsSpecifiedLengthAndFloatLayout) {
  StatusPayload p;
  p.reset_cause = 3;
  p.pulse_seen = true;
  p.reset_count = 0x0201;
  p.imu_period_ticks = 100000;
  p.accel_scale_mps2_per_lsb = 1.0f;   // 0x3F800000
  p.gyro_scale_radps_per_lsb = -2.0f;  // 0xC0000000
  p.mag_scale_uT_per_lsb = 0.5f;       // 0x3F000000
  p.profile = 2;
  const std::string f = EncodeStatus(0, 5, p);
  ASSERT_EQ(f.size(), 26u + kHeaderBytes + kCrcBytes);
  EXPECT_EQ(Hex(f.substr(kHeaderBytes, 26)),
            "03 01 01 02 40 42 0F 00 A0 86 01 00 00 00 80 3F 00 00 00 C0 00 00 00 3F 02 00");
}

TEST(McuFrameTest, AnyFlippedByteBreaksTheCrc) {
  ImuSamplePayload p;
  p.accel = {1, 2, 3};
  const std::string good = EncodeImuSample(1, 2, p);
  for (std::size_t i = 2; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    const std::vector<std::uint8_t> body(bad.begin() + 2, bad.end() - 2);
    const auto crc =
        static_cast<std::uint16_t>(static_cast<unsigned char>(bad[bad.size() - 2]) |
                                   (static_cast<unsigned char>(bad[bad.size() - 1]) << 8));
    EXPECT_NE(Crc16CcittFalse(body), crc) << "byte " << i;
  }
}

}  // namespace
}  // namespace hil::mcu

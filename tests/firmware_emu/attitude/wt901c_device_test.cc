// The WT901C emulator: packet layout and checksum, angle wrap and resolution, default output,
// configuration (unlock, rate, baud, save, reboot, reads), automatic rate reduction, gyro errors,
// determinism.
#include "hil/firmware_emu/attitude/wt901c_device.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/attitude/wit_packet.h"

#include "hex_bytes.h"
#include "wit_truth.h"

namespace hil::wit {
namespace {

std::string Hex(const std::string& b) {
  return hil::test::HexBytes(b, {.upper = true, .sep = " ", .trailing = true});
}

std::int16_t Field(const std::string& p, int k) {
  return static_cast<std::int16_t>(static_cast<unsigned char>(p[2 + 2 * k]) |
                                   (static_cast<unsigned char>(p[3 + 2 * k]) << 8));
}

TEST(WitPacketTest, ReferenceSheetExampleYaw90) {
  // seeds_001_003.md §C.1: roll 0, pitch 0, yaw +90°, version 0.
  EXPECT_EQ(Hex(EncodePacket(0x53, {0, 0, AngleToRaw(90.0), 0})),
            "55 53 00 00 00 00 00 40 00 00 E8 ");
}

TEST(WitPacketTest, AngleWrapsIntoMinus180To180WithTenthDegreeResolution) {
  EXPECT_EQ(AngleToRaw(180.0), -32768);  // +180° is not representable
  EXPECT_EQ(AngleToRaw(-180.0), -32768);
  EXPECT_EQ(AngleToRaw(190.0), AngleToRaw(-170.0));
  EXPECT_EQ(AngleToRaw(-540.0), -32768);
  EXPECT_EQ(AngleToRaw(179.99), 32766);
  EXPECT_EQ(AngleToRaw(0.1), 18);  // 0.1° = 18.2 LSB: finer than the paper's 0.1°
  EXPECT_NEAR(AngleToRaw(-123.4) / 32768.0 * 180.0, -123.4, 180.0 / 32768.0);
  EXPECT_EQ(ScaleToRaw(3000.0, kRateFullScale_dps), 32767);  // saturates
  EXPECT_EQ(ScaleToRaw(std::nan(""), kRateFullScale_dps), 0);
}

TEST(Wt901cDeviceTest, DefaultsAreTenHertzFourPacketsAt9600Baud) {
  Wt901cDevice dev(Wt901cConfig{}, 1);
  EXPECT_EQ(dev.baud(0), 9600);
  EXPECT_DOUBLE_EQ(dev.effective_rate_hz(), 10.0);
  const auto sent = test::Run(dev, test::TurnTruth{}, TimeFromSeconds(2.0));
  ASSERT_EQ(sent.size(), 80u);
  for (std::size_t i = 0; i < sent.size(); ++i) {
    const std::string& b = sent[i].msg.bytes;
    ASSERT_EQ(b.size(), kPacketSize);
    EXPECT_EQ(static_cast<unsigned char>(b[0]), 0x55);
    EXPECT_EQ(static_cast<unsigned char>(b[1]), 0x51 + i % 4);  // ascending within a cycle
    EXPECT_EQ(static_cast<unsigned char>(b[10]), Sum8(std::string_view(b).substr(0, 10)));
    EXPECT_EQ(ToNs(sent[i].msg.t_ready), static_cast<std::int64_t>(i / 4 + 1) * 100'000'000);
  }
}

TEST(Wt901cDeviceTest, YawCrossesPlus180IntoMinus180) {
  Wt901cConfig c;
  c.errors = Wt901cErrors{0, 0, 21, 0, 0, 0, 0};  // error-free: only the truth
  Wt901cDevice dev(c, 1);
  const auto sent = test::Run(dev, test::TurnTruth{}, TimeFromSeconds(1.0));  // 170° → 190°
  double first = 0, last = 0;
  for (const auto& s : sent) {
    if (static_cast<unsigned char>(s.msg.bytes[1]) != 0x53) continue;
    const double yaw = Field(s.msg.bytes, 2) / 32768.0 * 180.0;
    if (first == 0) first = yaw;
    last = yaw;
    EXPECT_GE(yaw, -180.0);
    EXPECT_LT(yaw, 180.0);
  }
  EXPECT_NEAR(first, 172.0, 0.01);
  EXPECT_NEAR(last, -170.0, 0.01);
}

TEST(Wt901cDeviceTest, RateChangeAndAutomaticReductionToTheBaudRate) {
  Wt901cDevice dev(Wt901cConfig{}, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.01), EncodeWriteCommand(0x03, 0x08), out);  // 50 Hz
  EXPECT_NEAR(dev.effective_rate_hz(), 9600.0 / 440.0, 1e-9);  // 44 bytes × 10 bits per cycle
  dev.OnHostBytes(0, TimeFromSeconds(0.02), EncodeWriteCommand(0x04, 0x06), out);  // 115200
  EXPECT_EQ(dev.baud(0), 115200);
  EXPECT_DOUBLE_EQ(dev.effective_rate_hz(), 50.0);
  EXPECT_EQ(dev.next_event_time(), TimeFromSeconds(0.04));
  dev.OnHostBytes(0, TimeFromSeconds(0.03), EncodeWriteCommand(0x02, 0x0008), out);  // 0x53 only
  EXPECT_DOUBLE_EQ(dev.effective_rate_hz(), 50.0);
  dev.OnHostBytes(0, TimeFromSeconds(0.04), EncodeWriteCommand(0x03, 0x0D), out);  // stop
  EXPECT_EQ(dev.effective_rate_hz(), 0.0);
  EXPECT_EQ(dev.next_event_time(), Time::max());
  dev.OnHostBytes(0, TimeFromSeconds(0.05), EncodeWriteCommand(0x03, 0x0C), out);  // single
  EXPECT_EQ(dev.next_event_time(), TimeFromSeconds(0.052));
  dev.OnEvent(test::TurnTruth{}.At(TimeFromSeconds(0.052)), out);
  EXPECT_EQ(out.serial.size(), 1u);  // one 0x53, then silence
  EXPECT_EQ(dev.next_event_time(), Time::max());
  dev.OnHostBytes(0, TimeFromSeconds(0.06), EncodeWriteCommand(0x03, 0x0A), out);  // WT931 only
  EXPECT_EQ(dev.reg(0x03), 0x0C);
  EXPECT_TRUE(out.serial.size() == 1u);  // writes are never answered
}

TEST(Wt901cDeviceTest, LockedFirmwareNeedsTheKeyAndSaveSurvivesAReboot) {
  Wt901cConfig c;
  c.require_unlock = true;
  Wt901cDevice dev(c, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(1), EncodeWriteCommand(0x03, 0x07), out);
  EXPECT_EQ(dev.reg(0x03), 0x06);
  EXPECT_EQ(dev.stats().writes_rejected_locked, 1u);
  dev.OnHostBytes(0, TimeFromSeconds(2), EncodeWriteCommand(0x69, 0xB588), out);
  dev.OnHostBytes(0, TimeFromSeconds(2.02), EncodeWriteCommand(0x03, 0x07), out);
  dev.OnHostBytes(0, TimeFromSeconds(2.04), EncodeWriteCommand(0x00, 0x0000), out);  // save
  dev.OnHostBytes(0, TimeFromSeconds(2.06), EncodeWriteCommand(0x02, 0x0002), out);  // not saved
  EXPECT_EQ(dev.reg(0x02), 0x0002);
  dev.OnHostBytes(0, TimeFromSeconds(2.08), EncodeWriteCommand(0x00, 0x00FF), out);  // reboot
  EXPECT_EQ(dev.reg(0x03), 0x07);
  EXPECT_EQ(dev.reg(0x02), 0x001E);
  EXPECT_EQ(dev.stats().reboots, 1u);
  EXPECT_EQ(dev.next_event_time(), TimeFromSeconds(2.13));
  dev.OnHostBytes(0, TimeFromSeconds(20), EncodeWriteCommand(0x03, 0x05), out);  // window over
  EXPECT_EQ(dev.reg(0x03), 0x07);
  EXPECT_TRUE(out.serial.empty());
}

TEST(Wt901cDeviceTest, FactoryResetRestoresDefaultsAndKeepsParsing) {
  Wt901cDevice dev(Wt901cConfig{}, 1);
  DeviceOutput out;
  // several commands in one write: rate change, factory reset, then a read after it
  dev.OnHostBytes(0, TimeFromSeconds(1),
                  EncodeWriteCommand(0x03, 0x07) + EncodeWriteCommand(0x00, 0x0001) +
                      EncodeWriteCommand(0x27, 0x0003),
                  out);
  EXPECT_EQ(dev.reg(0x03), 0x06);
  EXPECT_EQ(dev.stats().commands, 3u);
  EXPECT_EQ(dev.stats().reboots, 1u);
  ASSERT_EQ(out.serial.size(), 1u);
  EXPECT_EQ(Field(out.serial[0].bytes, 0), 0x06);
}

TEST(Wt901cDeviceTest, RegisterReadRepliesWith0x5FAndFourRegisters) {
  Wt901cDevice dev(Wt901cConfig{}, 1);
  DeviceOutput out;
  // split across two writes, after two garbage bytes
  dev.OnHostBytes(0, TimeFromSeconds(0.5), std::string("\x01\x02\xFF\xAA", 4), out);
  dev.OnHostBytes(0, TimeFromSeconds(0.5), std::string("\x27\x02\x00", 3), out);
  ASSERT_EQ(out.serial.size(), 1u);
  const std::string& p = out.serial[0].bytes;
  EXPECT_EQ(Hex(p), Hex(EncodePacket(0x5F, {0x001E, 0x0006, 0x0002, 0})));
  EXPECT_EQ(out.serial[0].t_ready, TimeFromSeconds(0.502));
  EXPECT_EQ(dev.stats().host_garbage_bytes, 2u);
}

TEST(Wt901cDeviceTest, ZeroingTheZAngle) {
  Wt901cConfig c;
  c.errors = Wt901cErrors{0, 0, 21, 0, 0, 0, 0};
  Wt901cDevice dev(c, 1);
  auto sent = test::Run(dev, test::TurnTruth{0.0, 10.0, 0.0, 0.5}, TimeFromSeconds(1.0));
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(1.0), EncodeWriteCommand(0x01, 0x0004), out);
  dev.OnEvent(test::TurnTruth{0.0, 10.0, 0.0, 0.5}.At(TimeFromSeconds(1.1)), out);
  ASSERT_EQ(out.serial.size(), 4u);
  EXPECT_NEAR(Field(out.serial[2].bytes, 2) / 32768.0 * 180.0, 1.0, 0.01);  // 11° − 10°
}

TEST(Wt901cDeviceTest, GyroBiasAndNoiseAreOfTheConfiguredGrade) {
  Wt901cDevice dev(Wt901cConfig{}, 7);
  const auto sent = test::Run(dev, test::TurnTruth{0.0, 0.0, 0.0, 0.5}, TimeFromSeconds(300.0));
  double sum = 0, sum2 = 0;
  int n = 0;
  for (const auto& s : sent) {
    if (static_cast<unsigned char>(s.msg.bytes[1]) != 0x52) continue;
    const double w = Field(s.msg.bytes, 2) / 32768.0 * kRateFullScale_dps;
    sum += w, sum2 += w * w, ++n;
  }
  ASSERT_EQ(n, 3000);
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, dev.gyro_bias_dps()[2], 0.005);
  EXPECT_NE(dev.gyro_bias_dps()[2], 0.0);
  const double lsb = kRateFullScale_dps / 32768.0;
  const double expected = std::sqrt(std::pow(0.01 * std::sqrt(21.0), 2) + lsb * lsb / 12);
  EXPECT_NEAR(sd, expected, 0.15 * expected);
}

TEST(Wt901cDeviceTest, SameSeedSameBytesOtherSeedOtherBytes) {
  auto bytes = [](std::uint64_t seed) {
    Wt901cDevice dev(Wt901cConfig{}, seed);
    std::string all;
    for (const auto& s : test::Run(dev, test::TurnTruth{}, TimeFromSeconds(1.0)))
      all += s.msg.bytes;
    return all;
  };
  EXPECT_EQ(bytes(3), bytes(3));
  EXPECT_NE(bytes(3), bytes(4));
}

TEST(Wt901cDeviceTest, UnknownCodesAtConstructionThrow) {
  Wt901cConfig c;
  c.rrate_code = 0x0A;
  EXPECT_THROW(Wt901cDevice(c, 1), std::invalid_argument);
  c = Wt901cConfig{};
  c.baud_code = 10;
  EXPECT_THROW(Wt901cDevice(c, 1), std::invalid_argument);
}

}  // namespace
}  // namespace hil::wit

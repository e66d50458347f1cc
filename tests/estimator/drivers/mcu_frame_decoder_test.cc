#include "hil/estimator/drivers/mcu_frame_decoder.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/drivers/mcu_imu_adapter.h"

namespace hil::estimator::drivers {
namespace {

std::string Hex(const char* hex) {
  std::string out;
  std::istringstream in(hex);
  std::string b;
  while (in >> b) out.push_back(static_cast<char>(std::stoi(b, nullptr, 16)));
  return out;
}

// worked examples of vectors/mcu/mcu_frame_protocol.md §7
const std::string kImu =
    Hex("A5 5A 01 01 0C 02 01 4E 61 BC 00 03 00 FB FF 00 01 FE FF 01 00 F0 FF A4 70");
const std::string kPulse = Hex("A5 5A 01 03 07 07 00 40 42 0F 00 D0 06 00 5C 26 05 01 20 C6");
const std::string kMag = Hex("A5 5A 01 02 06 08 00 90 05 10 00 2C 01 CE FF A8 FD A6 58");

std::vector<McuFrame> Decode(const std::vector<std::string>& pieces,
                             McuDecoderStats* st = nullptr) {
  std::vector<McuFrame> out;
  McuFrameDecoder d([&](const McuFrame& f) { out.push_back(f); });
  for (const auto& p : pieces) d.Feed(p);
  if (st) *st = d.stats();
  return out;
}

TEST(McuFrameDecoderTest, CrcCheckValue) { EXPECT_EQ(Crc16CcittFalse("123456789"), 0x29B1); }

TEST(McuFrameDecoderTest, DecodesWorkedExamples) {
  const auto f = Decode({kImu + kPulse + kMag});
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].type, McuFrame::Type::kImu);
  EXPECT_EQ(f[0].sequence, 0x0102);
  EXPECT_EQ(f[0].tick, 12345678u);
  EXPECT_EQ(f[0].accel_raw, (std::array<std::int16_t, 3>{3, -5, 256}));
  EXPECT_EQ(f[0].gyro_raw, (std::array<std::int16_t, 3>{-2, 1, -16}));
  EXPECT_EQ(f[1].type, McuFrame::Type::kTimePulse);
  EXPECT_EQ(f[1].tick, 1000000u);
  EXPECT_EQ(f[1].gps_week, 1744);
  EXPECT_EQ(f[1].tow_ms, 86400000u);
  EXPECT_TRUE(f[1].time_valid);
  EXPECT_EQ(f[2].mag_raw, (std::array<std::int16_t, 3>{300, -50, -600}));
}

TEST(McuFrameDecoderTest, SplitReadsGarbageAndBadCrc) {
  std::string bad = kImu;
  bad[15] ^= 0x40;  // corrupt a payload byte
  const std::string stream = "xx\xA5" + bad + "garbage" + kPulse + kMag;
  std::vector<std::string> bytes;
  for (char c : stream) bytes.emplace_back(1, c);  // one byte per read
  McuDecoderStats st;
  const auto f = Decode(bytes, &st);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].type, McuFrame::Type::kTimePulse);
  EXPECT_EQ(f[1].type, McuFrame::Type::kMag);
  EXPECT_EQ(st.bad_crc, 1u);
  EXPECT_GT(st.garbage_bytes, 8u);
}

TEST(McuFrameDecoderTest, GoldenVectorMatchesExpectedFrameCount) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  std::ifstream bin(std::string(src) + "/vectors/mcu/tactical_100hz_binary.bin", std::ios::binary);
  std::ifstream csv(std::string(src) + "/vectors/mcu/tactical_100hz_binary.expected.csv");
  if (!bin || !csv)
    GTEST_SKIP()
        << "vectors/mcu/tactical_100hz_binary.* not in this checkout (MCU branch not merged)";
  std::stringstream ss;
  ss << bin.rdbuf();
  std::vector<std::string> rows;
  for (std::string line; std::getline(csv, line);) {
    if (!line.empty() && line[0] != '#') rows.push_back(line);
  }
  const auto f = Decode({ss.str()});
  ASSERT_EQ(f.size(), rows.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    std::istringstream r(rows[i]);
    std::string offset, seq, type, tick;
    std::getline(r, offset, ',');
    std::getline(r, seq, ',');
    std::getline(r, type, ',');
    std::getline(r, tick, ',');
    EXPECT_EQ(f[i].sequence, std::stoul(seq)) << "row " << i;
    EXPECT_EQ(static_cast<int>(f[i].type), std::stoi(type)) << "row " << i;
    EXPECT_EQ(f[i].tick, std::stoul(tick)) << "row " << i;
  }
}

McuFrame Status(double accel_scale, double gyro_scale) {
  McuFrame f;
  f.type = McuFrame::Type::kStatus;
  f.accel_scale_mps2_per_lsb = static_cast<float>(accel_scale);
  f.gyro_scale_radps_per_lsb = static_cast<float>(gyro_scale);
  return f;
}

TEST(McuImuAdapterTest, MapsTicksOntoGpsTimeWithCrystalOffset) {
  // GIVEN a crystal 50 ppm fast and pulses at whole GPS seconds
  const double rate = 1e6 * (1 + 50e-6);
  McuImuAdapter a;
  a.Add(Status(0.01, 0.001));
  std::vector<ImuSample> out;
  const GpsTime t0 = GpsTimeFromWeek(1744, 0);
  for (int k = 0; k <= 300; ++k) {  // 3 s at 100 Hz, plus a tick wrap in the middle
    const double t_s = k * 0.01;
    const auto tick =
        static_cast<std::uint32_t>(std::llround(4294000000.0 + t_s * rate));  // wraps at 4294967296
    if (k % 100 == 0) {
      McuFrame p;
      p.type = McuFrame::Type::kTimePulse;
      p.tick = tick;
      p.time_valid = true;
      p.gps_week = 1744;
      p.tow_ms = static_cast<std::uint32_t>(k * 10);
      a.Add(p);
    }
    McuFrame f;
    f.type = McuFrame::Type::kImu;
    f.tick = tick;
    f.gyro_raw = {0, 0, 100};
    f.accel_raw = {0, 0, 981};
    if (auto s = a.Add(f)) out.push_back(*s);
  }
  // THEN samples are on GPS time to well under a microsecond after two pulses, with 0.01 s
  // intervals
  ASSERT_GT(out.size(), 250u);
  EXPECT_NEAR(a.clock().offset_ppm(), 50.0, 0.5);
  const ImuSample& last = out.back();
  EXPECT_NEAR(static_cast<double>((last.t - t0).count()) * 1e-9, 3.0, 1e-6);
  // (the ticks are integers: one tick of quantisation, 1 µs)
  EXPECT_NEAR(last.dt_s, 0.01, 1.1e-6);
  EXPECT_NEAR(last.delta_angle_B_rad.z(), 0.1 * last.dt_s, 1e-9);  // scales are f32 on the wire
  EXPECT_NEAR(last.delta_velocity_B_mps.z(), 9.81 * last.dt_s, 1e-7);
}

}  // namespace
}  // namespace hil::estimator::drivers

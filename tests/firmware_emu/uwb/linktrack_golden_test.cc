// LinkTrack Tag_Frame0 encoder: hand-checked field bytes, and the golden frames of vectors/uwb
// (a tag driving the first edge of paper 003's rectangle from A(−7, −7), anchors as in
// vectors/uwb/README.md). HIL_REGEN_VECTORS=1 rewrites the vector files.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"

namespace hil::linktrack {
namespace {

unsigned U8(const std::string& b, std::size_t i) { return static_cast<unsigned char>(b[i]); }

TEST(LinkTrackTagFrame0Test, FieldBytesByHand) {
  TagFrame0 f;
  f.id = 3;
  f.p_m = {-7.0, 1.5, 1.6};     // −7000 mm = 0xFFE4A8
  f.v_mps = {0.5, 0, 0};        // 5000 = 0x001388
  f.dis_m[0] = 12.345;          // 12345 = 0x003039
  f.angle_deg = {0, 0, -90.0};  // −9000 = 0xDCD8
  f.eop_m = {0.05, 0.07, 3.0};  // 5, 7, saturates at 255
  f.voltage_v = 4.987;          // 4987 = 0x137B
  f.local_time_ms = 0x01020304;
  const std::string b = EncodeTagFrame0(f);
  ASSERT_EQ(b.size(), 128u);
  EXPECT_EQ(U8(b, 0), 0x55u);
  EXPECT_EQ(U8(b, 1), 0x01u);
  EXPECT_EQ(U8(b, 2), 3u);
  EXPECT_EQ(U8(b, 3), 2u);  // tag
  EXPECT_EQ(U8(b, 4), 0xA8u);
  EXPECT_EQ(U8(b, 5), 0xE4u);
  EXPECT_EQ(U8(b, 6), 0xFFu);
  EXPECT_EQ(U8(b, 13), 0x88u);
  EXPECT_EQ(U8(b, 14), 0x13u);
  EXPECT_EQ(U8(b, 22), 0x39u);
  EXPECT_EQ(U8(b, 23), 0x30u);
  EXPECT_EQ(U8(b, 86), 0xD8u);
  EXPECT_EQ(U8(b, 87), 0xDCu);
  EXPECT_EQ(U8(b, 88 + 3), 0x3Fu);  // q0 = 1.0f = 0x3F800000
  EXPECT_EQ(U8(b, 108), 0x04u);
  EXPECT_EQ(U8(b, 111), 0x01u);
  EXPECT_EQ(U8(b, 117), 5u);
  EXPECT_EQ(U8(b, 118), 7u);
  EXPECT_EQ(U8(b, 119), 255u);
  EXPECT_EQ(U8(b, 120), 0x7Bu);
  EXPECT_EQ(U8(b, 121), 0x13u);
  unsigned sum = 0;
  for (std::size_t i = 0; i < 127; ++i) sum += U8(b, i);
  EXPECT_EQ(U8(b, 127), sum & 0xFFu);
  for (std::size_t i : {70u, 81u, 104u, 107u, 116u, 122u, 126u}) EXPECT_EQ(U8(b, i), 0u) << i;
}

TEST(LinkTrackTagFrame0Test, Int24Saturates) {
  TagFrame0 f;
  f.p_m = {9000.0, -9000.0, 0};
  const std::string b = EncodeTagFrame0(f);
  EXPECT_EQ(U8(b, 4) | U8(b, 5) << 8 | U8(b, 6) << 16, 0x7FFFFFu);
  EXPECT_EQ(U8(b, 7) | U8(b, 8) << 8 | U8(b, 9) << 16, 0x800000u);
}

std::string G(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", v + 0.0);
  return buf;
}

TEST(LinkTrackTagFrame0Test, GoldenFrames) {
  const Eigen::Vector2d anchors[4] = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
  std::string bin;
  std::ostringstream csv;
  csv << "# LinkTrack Tag_Frame0 golden frames: the values encoded (decode within one LSB).\n"
      << "# Generator: tests/firmware_emu/uwb/linktrack_golden_test.cc (HIL_REGEN_VECTORS=1)\n"
      << "system_time_ms,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,dis0_m,dis1_m,dis2_m,dis3_m,yaw_deg,"
         "gyro_z_radps,acc_z_mps2,eop_x_m,voltage_v\n";
  for (int k = 0; k < 10; ++k) {  // 5 Hz (the paper's sampling), 0.5 m/s north from A(−7, −7)
    TagFrame0 f;
    f.id = 0;
    const double t_s = 0.2 * k;
    f.p_m = {-7.0 + 0.0123 * k, -7.0 + 0.5 * t_s, 1.6};
    f.v_mps = {0.0, 0.5, 0.0};
    for (int a = 0; a < 4; ++a) f.dis_m[a] = (f.p_m.head<2>() - anchors[a]).norm();
    f.angle_deg = {0.0, 0.0, 90.0 - 0.7 * k};
    f.gyro_radps = {0.0f, 0.0f, -0.061f};
    f.acc_mps2 = {0.0f, 0.0f, 9.80665f};
    const double half = (90.0 - 0.7 * k) * std::numbers::pi / 360.0;
    f.quat_wxyz = {static_cast<float>(std::cos(half)), 0.0f, 0.0f,
                   static_cast<float>(std::sin(half))};
    f.local_time_ms = static_cast<std::uint32_t>(1000 + 200 * k);
    f.system_time_ms = static_cast<std::uint32_t>(50000 + 200 * k);
    f.eop_m = {0.08, 0.09, 0.2};
    f.voltage_v = 4.95 - 0.001 * k;
    bin += EncodeTagFrame0(f);
    csv << f.system_time_ms << "," << G(f.p_m.x()) << "," << G(f.p_m.y()) << "," << G(f.p_m.z())
        << "," << G(f.v_mps.x()) << "," << G(f.v_mps.y()) << "," << G(f.v_mps.z());
    for (int a = 0; a < 4; ++a) csv << "," << G(f.dis_m[a]);
    csv << "," << G(f.angle_deg.z()) << "," << G(f.gyro_radps.z()) << "," << G(f.acc_mps2.z())
        << "," << G(f.eop_m.x()) << "," << G(f.voltage_v) << "\n";
  }
  const std::string dir = HIL_TEST_SOURCE_DIR "/vectors/uwb/";
  if (const char* r = std::getenv("HIL_REGEN_VECTORS"); r && std::string(r) == "1") {
    std::ofstream(dir + "linktrack_tag_frame0.bin", std::ios::binary) << bin;
    std::ofstream(dir + "linktrack_tag_frame0.expected.csv") << csv.str();
  }
  std::ifstream fb(dir + "linktrack_tag_frame0.bin", std::ios::binary);
  std::ifstream fc(dir + "linktrack_tag_frame0.expected.csv");
  std::stringstream sb, sc;
  sb << fb.rdbuf();
  sc << fc.rdbuf();
  EXPECT_EQ(sb.str(), bin) << "HIL_REGEN_VECTORS=1 rewrites";
  EXPECT_EQ(sc.str(), csv.str());
}

}  // namespace
}  // namespace hil::linktrack

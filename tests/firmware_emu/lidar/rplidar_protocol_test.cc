// RPLIDAR request framing and response encoding against the bytes of the protocol table
// (seeds_001_003.md §C.4), worked by hand.
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/lidar/rplidar_request.h"
#include "hil/firmware_emu/lidar/rplidar_response.h"

namespace hil::lidar {
namespace {

std::string Bytes(std::initializer_list<int> b) {
  std::string s;
  for (const int v : b) s.push_back(static_cast<char>(v));
  return s;
}

TEST(RplidarProtocol, DescriptorsOfTheTable) {
  EXPECT_EQ(EncodeDescriptor(5, true, DataType::kScanNode),
            Bytes({0xA5, 0x5A, 0x05, 0x00, 0x00, 0x40, 0x81}));
  EXPECT_EQ(EncodeDescriptor(84, true, DataType::kExpressCapsule),
            Bytes({0xA5, 0x5A, 0x54, 0x00, 0x00, 0x40, 0x82}));
  EXPECT_EQ(EncodeDescriptor(20, false, DataType::kDeviceInfo),
            Bytes({0xA5, 0x5A, 0x14, 0x00, 0x00, 0x00, 0x04}));
  EXPECT_EQ(EncodeDescriptor(3, false, DataType::kHealth),
            Bytes({0xA5, 0x5A, 0x03, 0x00, 0x00, 0x00, 0x06}));
  EXPECT_EQ(EncodeDescriptor(4, false, DataType::kSampleRate),
            Bytes({0xA5, 0x5A, 0x04, 0x00, 0x00, 0x00, 0x15}));
}

TEST(RplidarProtocol, RequestsAndTheirChecksum) {
  EXPECT_EQ(EncodeRequest(0x20), Bytes({0xA5, 0x20}));
  // express scan, mode 0: A5 82 05 00 00 00 00 00 CS, CS = A5 ^ 82 ^ 05 = 0x22
  EXPECT_EQ(EncodeRequest(0x82, std::string(5, '\0')),
            Bytes({0xA5, 0x82, 0x05, 0, 0, 0, 0, 0, 0x22}));
  std::vector<RequestFrame> got;
  RequestReader r([&](const RequestFrame& f) { got.push_back(f); });
  r.Feed(Bytes({0x00, 0xA5}));
  r.Feed(
      Bytes({0x52, 0xA5, 0xF0, 0x02, 0x94, 0x02, 0xC1}));  // GET_HEALTH; PWM 660: 0xA5^F0^02^94^02
  r.Feed(Bytes({0xA5, 0xF0, 0x02, 0x94, 0x02, 0x00}));     // bad checksum
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].cmd, 0x52);
  EXPECT_EQ(got[1].cmd, 0xF0);
  EXPECT_EQ(got[1].payload, Bytes({0x94, 0x02}));
  EXPECT_EQ(r.stats().garbage_bytes, 1u + 5u);  // the 00; after the bad one its 5 other bytes
  EXPECT_EQ(r.stats().bad_checksum, 1u);
}

TEST(RplidarProtocol, NodeBitsByHand) {
  // quality 47, S = 1, angle 90.5° (q6 5792), 1234.25 mm (q2 4937)
  // byte0 = 47 << 2 | 0 << 1 | 1 = 0xBD; angle word = 5792 << 1 | 1 = 11585 = 0x2D41
  EXPECT_EQ(EncodeNode({47, true, 5792, 4937}), Bytes({0xBD, 0x41, 0x2D, 0x49, 0x13}));
  // S = 0: !S = 1 → byte0 = 47 << 2 | 2 = 0xBE
  EXPECT_EQ(static_cast<unsigned char>(EncodeNode({47, false, 0, 0})[0]), 0xBE);
}

TEST(RplidarProtocol, CapsuleLayoutAndChecksum) {
  ExpressCapsule c;
  c.start_angle_q6 = 64 * 10;  // 10°
  c.new_scan = true;
  c.distance_mm.fill(0);
  c.distance_mm[0] = 1000;  // cabin 0, word 1: 1000 << 2 = 4000 = 0x0FA0
  c.distance_mm[3] = 2;     // cabin 1, word 2: 8 = 0x0008
  const std::string b = EncodeCapsule(c);
  ASSERT_EQ(b.size(), 84u);
  EXPECT_EQ(static_cast<unsigned char>(b[2]), 0x80);  // 640 = 0x0280, | 0x8000
  EXPECT_EQ(static_cast<unsigned char>(b[3]), 0x82);
  EXPECT_EQ(static_cast<unsigned char>(b[4]), 0xA0);
  EXPECT_EQ(static_cast<unsigned char>(b[5]), 0x0F);
  EXPECT_EQ(static_cast<unsigned char>(b[11]), 0x08);
  // checksum = XOR of bytes 2…83 = 80 ^ 82 ^ A0 ^ 0F ^ 08 = 0xA5: nibbles in bytes 0 and 1
  EXPECT_EQ(static_cast<unsigned char>(b[0]), 0xA5);
  EXPECT_EQ(static_cast<unsigned char>(b[1]), 0x5A);
}

}  // namespace
}  // namespace hil::lidar

// The RTCM 3 transport layer: CRC-24Q against its published check value and against the example
// 1005 frame of RTCM 10403.x (as reproduced in the decoders' test suites), framing of bodies, and
// the splitter's resynchronisation after corrupted bytes.
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include <string>

#include <gtest/gtest.h>

namespace hil::rtcm3 {
namespace {

std::string Bytes(std::initializer_list<int> v) {
  std::string s;
  for (const int b : v) s.push_back(static_cast<char>(b));
  return s;
}

// The standard's 1005 example: station 2003, ARP (1114104.5999, -4850729.7108, 3975521.4643) m.
const std::string kExample1005 =
    Bytes({0xD3, 0x00, 0x13, 0x3E, 0xD7, 0xD3, 0x02, 0x02, 0x98, 0x0E, 0xDE, 0xEF, 0x34,
           0xB4, 0xBD, 0x62, 0xAC, 0x09, 0x41, 0x98, 0x6F, 0x33, 0x36, 0x0B, 0x98});

TEST(Rtcm3Frame, Crc24qCheckValue) {
  // CRC-24Q of the ASCII digits 1-9 (the CRC catalogue's check value)
  EXPECT_EQ(Crc24q("123456789"), 0xCDE703U);
  EXPECT_EQ(Crc24q(""), 0U);
}

TEST(Rtcm3Frame, FramesTheStandardExampleByteForByte) {
  const std::string body = kExample1005.substr(3, 19);
  EXPECT_EQ(Frame(body), kExample1005);
  EXPECT_EQ(MessageNumber(body), 1005);
}

TEST(Rtcm3Frame, LengthFieldAndLimits) {
  const std::string f = Frame(std::string(300, '\x55'));
  ASSERT_EQ(f.size(), 306U);
  EXPECT_EQ(static_cast<unsigned char>(f[1]), 0x01);  // 300 = 0x12C: 6 zero bits, then 01
  EXPECT_EQ(static_cast<unsigned char>(f[2]), 0x2C);
  EXPECT_NO_THROW(Frame(std::string(1023, 'a')));
  EXPECT_THROW(Frame(std::string(1024, 'a')), std::length_error);
}

TEST(Rtcm3Frame, SplitFindsFramesBetweenNoiseAndCountsBadCrc) {
  std::string corrupted = kExample1005;
  corrupted[10] = static_cast<char>(corrupted[10] ^ 0x01);
  const std::string stream =
      std::string("\x00\xD3\x7F", 3) + kExample1005 + corrupted + Frame("\x3E\xE0") + "tail";
  const SplitResult r = Split(stream);
  ASSERT_EQ(r.bodies.size(), 2U);
  EXPECT_EQ(r.bodies[0], kExample1005.substr(3, 19));
  EXPECT_EQ(r.bodies[1], std::string("\x3E\xE0"));
  EXPECT_EQ(r.crc_errors, 1U);
}

}  // namespace
}  // namespace hil::rtcm3

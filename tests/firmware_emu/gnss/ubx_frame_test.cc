#include "hil/firmware_emu/gnss/ubx_frame.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::gnss::ubx {
namespace {

std::string Bytes(std::initializer_list<int> b) {
  std::string s;
  for (int v : b) s += static_cast<char>(v);
  return s;
}

// Frames quoted in shared/reference/ublox5.md §1 (ArduPilot and a u-blox 5 configuration tool).
TEST(UbxFrameTest, ReproducesPublishedFrames) {
  EXPECT_EQ(Frame(0x06, 0x01, std::vector<std::uint8_t>{0x01, 0x06, 0x01}),
            Bytes({0xB5, 0x62, 0x06, 0x01, 0x03, 0x00, 0x01, 0x06, 0x01, 0x12, 0x4F}));
  EXPECT_EQ(
      Frame(0x06, 0x16, std::vector<std::uint8_t>{0x00, 0x03, 0x03, 0, 0, 0, 0, 0}),
      Bytes({0xB5, 0x62, 0x06, 0x16, 0x08, 0x00, 0x00, 0x03, 0x03, 0, 0, 0, 0, 0, 0x2A, 0xB1}));
  EXPECT_EQ(Frame(0x06, 0x01, std::vector<std::uint8_t>{0xF0, 0x01, 0, 0, 0, 0, 0, 1}),
            Bytes({0xB5, 0x62, 0x06, 0x01, 0x08, 0x00, 0xF0, 0x01, 0, 0, 0, 0, 0, 1, 0x01, 0x2B}));
  Writer tp;
  tp.U4(1000000).U4(800000).I1(1).U1(1).U1(0).U1(0).I2(50).I2(0).I4(0);
  EXPECT_EQ(
      Frame(0x06, 0x07, tp),
      Bytes({0xB5, 0x62, 0x06, 0x07, 0x14, 0x00, 0x40, 0x42, 0x0F, 0x00, 0x00, 0x35, 0x0C, 0x00,
             0x01, 0x01, 0x00, 0x00, 0x32, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x27, 0x47}));
}

TEST(UbxFrameTest, WriterIsLittleEndianAndReaderInvertsIt) {
  Writer w;
  w.U2(0x1234).I4(-2).U4(0xA1B2C3D4).I2(-300).Chars("ab", 4);
  const std::vector<std::uint8_t> expect{0x34, 0x12, 0xFE, 0xFF, 0xFF, 0xFF, 0xD4, 0xC3,
                                         0xB2, 0xA1, 0xD4, 0xFE, 'a',  'b',  0,    0};
  EXPECT_EQ(w.bytes(), expect);
  const Reader r(w.bytes());
  EXPECT_EQ(r.U2(0), 0x1234);
  EXPECT_EQ(r.I4(2), -2);
  EXPECT_EQ(r.U4(6), 0xA1B2C3D4u);
  EXPECT_EQ(r.I2(10), -300);
  EXPECT_EQ(r.U1(100), 0);  // out of range reads are zero
}

TEST(UbxFrameTest, ParserSplitsMixedInputAndDropsCorruptFrames) {
  const std::string poll = Frame(0x0A, 0x04, std::vector<std::uint8_t>{});
  std::string corrupt = Frame(0x06, 0x08, std::vector<std::uint8_t>{0xE8, 0x03, 1, 0, 0, 0});
  corrupt[7] = 0x04;  // payload changed, checksum stale
  const std::string stream = "junk" + poll + "$PUBX,00*33\r\n" + corrupt + "$PUBX,04*00\r\n" +
                             Frame(0x06, 0x01, std::vector<std::uint8_t>{0x01, 0x06, 0x01});
  InputParser p;
  std::vector<InputMessage> all;
  for (char c : stream) {  // byte by byte, as a UART delivers them
    auto m = p.Feed(std::string(1, c));
    all.insert(all.end(), m.begin(), m.end());
  }
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].kind, InputMessage::Kind::kUbx);
  EXPECT_EQ(all[0].cls, 0x0A);
  EXPECT_EQ(all[0].id, 0x04);
  EXPECT_TRUE(all[0].payload.empty());
  EXPECT_EQ(all[1].kind, InputMessage::Kind::kNmea);
  EXPECT_EQ(all[1].sentence, "PUBX,00");
  EXPECT_EQ(all[2].cls, 0x06);
  EXPECT_EQ(all[2].payload, (std::vector<std::uint8_t>{0x01, 0x06, 0x01}));
  EXPECT_EQ(p.discarded_frames(), 2u);  // the corrupt frame and the PUBX,04 with a wrong checksum
}

TEST(UbxFrameTest, ParseFrameAtReadsAWholeFrameAndStopsAtItsEnd) {
  const std::string f = Bytes({0xB5, 0x62, 0x06, 0x01, 0x03, 0x00, 0x01, 0x06, 0x01, 0x12, 0x4F});
  const std::string bytes = f + "trailing";
  const FrameAt u = ParseFrameAt(bytes);  // its payload is a view into `bytes`
  EXPECT_EQ(u.status, FrameAtStatus::kFrame);
  EXPECT_EQ(u.cls, 0x06);
  EXPECT_EQ(u.id, 0x01);
  EXPECT_EQ(u.frame_size(), f.size());
  EXPECT_EQ(u.payload, Bytes({0x01, 0x06, 0x01}));
}

TEST(UbxFrameTest, ParseFrameAtTellsACutHeaderATooLongOrCutFrameAndABadChecksum) {
  const std::string f = Bytes({0xB5, 0x62, 0x06, 0x01, 0x03, 0x00, 0x01, 0x06, 0x01, 0x12, 0x4F});
  EXPECT_EQ(ParseFrameAt(f.substr(0, 5)).status, FrameAtStatus::kHeaderCut);
  EXPECT_EQ(ParseFrameAt(f.substr(0, 10)).status, FrameAtStatus::kCut);
  EXPECT_EQ(ParseFrameAt(f, 2).status, FrameAtStatus::kTooLong) << "3 payload bytes over 2";
  EXPECT_EQ(ParseFrameAt(f.substr(0, 6), 2).status, FrameAtStatus::kTooLong)
      << "the length is judged before the end";
  std::string bad = f;
  bad[7] = 0x07;
  const FrameAt u = ParseFrameAt(bad);
  EXPECT_EQ(u.status, FrameAtStatus::kBadChecksum);
  EXPECT_EQ(u.payload_length, 3u);
  EXPECT_TRUE(u.payload.empty());
}

}  // namespace
}  // namespace hil::gnss::ubx

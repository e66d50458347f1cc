// Benewake framing and field codec: the reference sheet's worked example, checksums, the command
// reader's tolerance (pieces, garbage, bad and zero checksums).
#include "hil/firmware_emu/rangefinder/benewake_framing.h"

#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rangefinder/benewake_codec.h"

namespace hil::rangefinder {
namespace {

std::string Bytes(std::initializer_list<int> b) {
  std::string s;
  for (const int v : b) s.push_back(static_cast<char>(v));
  return s;
}

TEST(BenewakeFraming, DataFrameOfTheWorkedExample) {
  // seeds_001_003.md §C.3.1: 50 cm, Amp 1000, 40 °C → 59 59 32 00 E8 03 40 09 18
  const DataFields f{50, 1000, TemperatureToRaw(40.0)};
  EXPECT_EQ(f.temp_raw, 0x0940);
  const std::string frame = FrameData(EncodeDataFields(f));
  EXPECT_EQ(frame, Bytes({0x59, 0x59, 0x32, 0x00, 0xE8, 0x03, 0x40, 0x09, 0x18}));
  const DataFields back = DecodeDataFields(frame);
  EXPECT_EQ(back.dist, 50);
  EXPECT_EQ(back.amp, 1000);
  EXPECT_DOUBLE_EQ(TemperatureFromRaw(back.temp_raw), 40.0);
}

TEST(BenewakeFraming, CommandFramesOfTheManual) {
  // baud 9600: 5A 08 06 80 25 00 00 CS (sum 0x5A+8+6+0x80+0x25 = 0x10D → 0x0D)
  EXPECT_EQ(FrameCommand(0x06, U32Payload(9600)),
            Bytes({0x5A, 0x08, 0x06, 0x80, 0x25, 0x00, 0x00, 0x0D}));
  // frame rate 100 Hz: 5A 06 03 64 00 CS (0x5A+6+3+0x64 = 0xC7)
  EXPECT_EQ(FrameCommand(0x03, U16Payload(100)), Bytes({0x5A, 0x06, 0x03, 0x64, 0x00, 0xC7}));
  EXPECT_EQ(FrameCommand(0x11, ""), Bytes({0x5A, 0x04, 0x11, 0x6F}));
  EXPECT_EQ(PixLine(0.504), "0.50\r\n");
}

TEST(CommandReader, PiecesGarbageAndChecksums) {
  std::vector<CommandFrame> got;
  CommandReader r([&](const CommandFrame& f) { got.push_back(f); });
  const std::string rate = FrameCommand(0x03, U16Payload(250));
  r.Feed(Bytes({0x13, 0x37}));  // 2 garbage bytes
  r.Feed(rate.substr(0, 3));    // a frame in two pieces
  r.Feed(rate.substr(3));
  r.Feed(Bytes({0x5A, 0x05, 0x07, 0x00, 0x77}));  // bad checksum (sum is 0x66)
  r.Feed(Bytes({0x5A, 0x05, 0x07, 0x01, 0x00}));  // checksum 00: accepted
  r.Feed(Bytes({0x5A, 0x02}));                    // LEN 2 cannot be: garbage
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].id, 0x03);
  EXPECT_EQ(PayloadU16(got[0].payload).value(), 250);
  EXPECT_FALSE(got[0].checksum_zero);
  EXPECT_EQ(got[1].id, 0x07);
  EXPECT_TRUE(got[1].checksum_zero);
  EXPECT_EQ(r.stats().bad_checksum, 1u);
  EXPECT_EQ(r.stats().zero_checksum, 1u);
  // 2 leading bytes; after the bad frame the search resumes one byte on: its 4 other bytes
  // (05 07 00 77) are garbage; then 5A 02 and the 02 after it
  EXPECT_EQ(r.stats().garbage_bytes, 2u + 4u + 2u);
}

}  // namespace
}  // namespace hil::rangefinder

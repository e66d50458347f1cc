// The rover's incremental RTCM 3 parser: a base stream fed byte by byte gives back every frame
// the base sent, bodies intact; a flipped bit makes that frame crcFailed (its message number
// still read) and the next frames are found again; bytes outside frames are skipped.
#include "hil/firmware_emu/rtk/rtcm3_stream.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include "rtk_base_fixture.h"

namespace hil::rtcm3 {
namespace {

std::vector<ReceivedFrame> FeedAll(const std::string& s, StreamParser& p) {
  std::vector<ReceivedFrame> out;
  for (const char c : s) p.Feed(c, out);
  return out;
}

TEST(Rtcm3Stream, ByteByByteGivesTheSentFrames) {
  const std::string stream = rtk::test::BaseStream(rtk::test::KarajBase(MsmKind::kMsm7), 12, 5);
  const SplitResult whole = Split(stream);
  StreamParser p;
  const auto frames = FeedAll("\x01garbage" + stream, p);
  ASSERT_EQ(frames.size(), whole.bodies.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_FALSE(frames[k].crc_failed);
    EXPECT_EQ(frames[k].body, whole.bodies[k]);
  }
  EXPECT_EQ(frames[0].message_number(), 1006);
  EXPECT_EQ(frames[0].station_id(), 1234);
  EXPECT_EQ(frames[1].message_number(), 1077);
  EXPECT_EQ(frames[1].station_id(), 1234);
  EXPECT_EQ(p.skipped_bytes(), 8U);
}

TEST(Rtcm3Stream, CorruptFrameIsReportedAndTheNextFound) {
  std::string stream = rtk::test::BaseStream(rtk::test::KarajBase(MsmKind::kMsm4), 3, 5);
  const std::size_t first_len = 6 + (static_cast<unsigned char>(stream[2]) |
                                     (static_cast<unsigned char>(stream[1]) & 3U) << 8);
  stream[first_len + 20] = static_cast<char>(stream[first_len + 20] ^ 0x01);  // in the 1st MSM
  StreamParser p;
  const auto frames = FeedAll(stream, p);
  ASSERT_EQ(frames.size(), 4U);  // 1006, 1074 (failed), 1074, 1074
  EXPECT_FALSE(frames[0].crc_failed);
  EXPECT_TRUE(frames[1].crc_failed);
  EXPECT_EQ(frames[1].message_number(), 1074);
  EXPECT_FALSE(frames[2].crc_failed);
  EXPECT_FALSE(frames[3].crc_failed);
}

}  // namespace
}  // namespace hil::rtcm3

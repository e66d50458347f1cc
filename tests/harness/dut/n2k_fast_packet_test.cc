#include "hil/harness/dut/n2k_fast_packet.h"

#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/outputs/n2k_encoder.h"

namespace hil::harness {
namespace {

std::string Bytes(const estimator::outputs::CanFrame& f) {
  return std::string(reinterpret_cast<const char*>(f.data.data()), f.len);
}

TEST(N2kFastPacketTest, PgnOfIdentifiers) {
  EXPECT_EQ(N2kPgnFromId(0x0DF80580), 129029u);  // PDU2
  EXPECT_EQ(N2kPgnFromId(0x09F80180), 129025u);
  EXPECT_EQ(N2kPgnFromId(0x18EAFF80), 0xEA00u);  // PDU1: destination not part of the PGN
  EXPECT_EQ(N2kSourceFromId(0x0DF80580), 0x80);
}

// navd's 129029 encoder → frames → reassembly gives the 43-byte payload back
TEST(N2kFastPacketTest, RoundTripOfNavdEncoder) {
  const auto fp = estimator::outputs::EncodeGnssPosition(7, 15866, 28800.25, 52.1234567, -1.7654321,
                                                         81.5, 1, 9, 0.9, 5, 0x80);
  ASSERT_EQ(fp.count, 7);
  N2kFastPacketAssembler a;
  std::optional<std::string> msg;
  for (int i = 0; i < fp.count; ++i) {
    EXPECT_FALSE(msg) << "complete before the last frame";
    msg = a.Add(0x80, 129029, Bytes(fp.frames[static_cast<std::size_t>(i)]));
  }
  ASSERT_TRUE(msg);
  ASSERT_EQ(msg->size(), 43u);
  EXPECT_EQ(static_cast<unsigned char>((*msg)[0]), 7);  // SID
  std::int64_t lat = 0;
  for (int k = 7; k >= 0; --k)
    lat = (lat << 8) | static_cast<unsigned char>((*msg)[7 + static_cast<std::size_t>(k)]);
  EXPECT_NEAR(static_cast<double>(lat) * 1e-16, 52.1234567, 1e-12);
  EXPECT_EQ(a.stats().messages, 1u);
  EXPECT_EQ(a.stats().out_of_turn, 0u);
}

TEST(N2kFastPacketTest, InterleavedSourcesAndLostFrames) {
  const auto m1 =
      estimator::outputs::EncodeGnssPosition(1, 15866, 10.0, 10.0, 20.0, 0, 1, 9, 0.9, 1, 0x80);
  const auto m2 =
      estimator::outputs::EncodeGnssPosition(2, 15866, 10.0, -10.0, -20.0, 0, 1, 9, 0.9, 3, 0x81);
  N2kFastPacketAssembler a;
  int complete = 0;
  for (int i = 0; i < 7; ++i) {  // two sources, frame by frame interleaved
    complete += a.Add(0x80, 129029, Bytes(m1.frames[static_cast<std::size_t>(i)])).has_value();
    complete += a.Add(0x81, 129029, Bytes(m2.frames[static_cast<std::size_t>(i)])).has_value();
  }
  EXPECT_EQ(complete, 2);
  // a lost frame: the message is dropped, counted, and the next one is read again
  N2kFastPacketAssembler b;
  for (int i = 0; i < 7; ++i) {
    if (i == 3) continue;
    EXPECT_FALSE(b.Add(0x80, 129029, Bytes(m1.frames[static_cast<std::size_t>(i)])));
  }
  EXPECT_EQ(b.stats().out_of_turn, 3u);  // frames 4, 5, 6
  std::optional<std::string> again;
  for (int i = 0; i < 7; ++i)
    again = b.Add(0x80, 129029, Bytes(m1.frames[static_cast<std::size_t>(i)]));
  EXPECT_TRUE(again);
  // a new first frame while a message is under way abandons it
  N2kFastPacketAssembler c;
  c.Add(0x80, 129029, Bytes(m1.frames[0]));
  c.Add(0x80, 129029, Bytes(m1.frames[1]));
  c.Add(0x80, 129029, Bytes(m1.frames[0]));
  EXPECT_EQ(c.stats().abandoned, 1u);
  // bad first frames
  EXPECT_FALSE(c.Add(0x80, 129029, std::string("\x00", 1)));
  EXPECT_FALSE(c.Add(0x80, 129029, std::string("\x00\xF0\x01", 3)));  // announces 240 > 223 bytes
  EXPECT_FALSE(c.Add(0x80, 129029, std::string()));
  EXPECT_EQ(c.stats().bad_frames, 3u);
}

TEST(N2kFastPacketTest, ShortMessageInTheFirstFrame) {
  N2kFastPacketAssembler a;
  const auto m = a.Add(0x10, 130000,
                       std::string("\x20\x04"
                                   "abcdXX",
                                   8));
  ASSERT_TRUE(m);
  EXPECT_EQ(*m, "abcd");
}

}  // namespace
}  // namespace hil::harness

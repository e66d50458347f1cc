// The controller's side of the SLCAN adapter (estimator/guidance/slcan_codec.h), an implementation
// independent of the adapter emulator, against the same golden file (vectors/slcan/): it writes
// the session's host records byte for byte and reads the adapter's answers and frames.
#include "hil/estimator/guidance/slcan_codec.h"

#include <gtest/gtest.h>

#include "joined_text.h"
#include "slcan_golden.h"

namespace hil::estimator::guidance {
namespace {

using hil::test::Joined;

SlcanReply ReadAll(SlcanReader& r, const std::string& bytes) {
  SlcanReply last = SlcanReply::kNone;
  for (const char c : bytes) {
    const SlcanReply x = r.Feed(c);
    if (x != SlcanReply::kNone) last = x;
  }
  return last;
}

TEST(SlcanCodecTest, ExtendedGoldenFramesFormatAndRead) {
  const test::SlcanGolden g = test::ReadSlcanGolden();
  int extended = 0;
  for (const test::SlcanGoldenFrame& f : g.frames) {
    SlcanReader r;
    const SlcanReply kind = ReadAll(r, f.record + "\r");
    if (!f.extended || f.rtr) {
      EXPECT_EQ(kind, SlcanReply::kOtherFrame) << f.record;
      continue;
    }
    ++extended;
    ASSERT_EQ(kind, SlcanReply::kFrame) << f.record;
    EXPECT_EQ(r.frame().id, f.id);
    ASSERT_EQ(r.frame().len, f.data.size());
    for (std::size_t i = 0; i < f.data.size(); ++i) EXPECT_EQ(r.frame().data[i], f.data[i]);
    if (f.check != "both") continue;
    IsobusFrame x;
    x.id = f.id;
    x.len = static_cast<std::uint8_t>(f.data.size());
    for (std::size_t i = 0; i < f.data.size(); ++i) x.data[i] = f.data[i];
    EXPECT_EQ(FormatSlcanExtendedFrame(x).view(), f.record + "\r");
  }
  EXPECT_GE(extended, 7);
}

TEST(SlcanCodecTest, WritesTheSessionsStartUpAndReadsTheAnswers) {
  const test::SlcanGolden g = test::ReadSlcanGolden();
  SlcanRecord rate;
  ASSERT_TRUE(FormatSlcanBitrate(250000, rate));
  EXPECT_FALSE(FormatSlcanBitrate(333000, rate));
  FormatSlcanBitrate(250000, rate);
  bool saw_close = false, saw_rate = false, saw_open = false;
  int transmitted = 0, refused = 0, acks = 0;
  for (const test::SlcanGoldenExchange& x : g.session) {
    saw_close = saw_close || x.host == FormatSlcanClose().view();
    saw_rate = saw_rate || x.host == rate.view();
    saw_open = saw_open || x.host == FormatSlcanOpen().view();
    SlcanReader r;
    const SlcanReply kind = ReadAll(r, x.reply);
    transmitted += kind == SlcanReply::kTransmitted ? 1 : 0;
    refused += kind == SlcanReply::kRefused ? 1 : 0;
    acks += kind == SlcanReply::kAck ? 1 : 0;
  }
  EXPECT_TRUE(saw_close && saw_rate && saw_open) << "slcand's start-up: C, S5, O";
  EXPECT_EQ(transmitted, 2);
  EXPECT_EQ(refused, 5);
  EXPECT_GE(acks, 9);
}

TEST(SlcanCodecTest, SkipsTheAdaptersTimeStampAndCountsMalformedRecords) {
  SlcanReader r;
  EXPECT_EQ(ReadAll(r, "T0CACFF1C1AB04D2\r"), SlcanReply::kFrame);
  EXPECT_EQ(r.frame().id, 0x0CACFF1Cu);
  EXPECT_EQ(r.frame().data[0], 0xAB);
  EXPECT_EQ(ReadAll(r, "T0CACFF1C1ABX\r"), SlcanReply::kMalformed);
  EXPECT_EQ(ReadAll(r, Joined(std::string(60, 'T'), "\r")), SlcanReply::kMalformed);
  EXPECT_EQ(r.malformed(), 2u);
}

}  // namespace
}  // namespace hil::estimator::guidance

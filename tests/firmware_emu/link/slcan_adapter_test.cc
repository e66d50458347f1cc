// The emulated SLCAN adapter (firmware_emu/link: slcan_framing.h, slcan_adapter.h) against the
// golden vectors of vectors/slcan/slcan_golden.txt: records to frames and back, the records it
// refuses, and a whole session (slcand's start-up, ISOBUS frames, refusals) answer by answer.
#include "hil/firmware_emu/link/slcan_adapter.h"

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/slcan_framing.h"

#include "slcan_golden.h"

namespace hil::link {
namespace {

const char* ErrorName(SlcanFrameError e) {
  switch (e) {
    case SlcanFrameError::kNone:
      return "none";
    case SlcanFrameError::kNotAFrame:
      return "not_a_frame";
    case SlcanFrameError::kBadId:
      return "bad_id";
    case SlcanFrameError::kBadLength:
      return "bad_length";
    case SlcanFrameError::kBadData:
      return "bad_data";
  }
  return "?";
}

TEST(SlcanFramingTest, GoldenFramesEncodeAndDecode) {
  const test::SlcanGolden g = test::ReadSlcanGolden();
  ASSERT_GE(g.frames.size(), 10u);
  for (const test::SlcanGoldenFrame& f : g.frames) {
    CanFrame d;
    ASSERT_EQ(DecodeSlcanFrame(f.record, d), SlcanFrameError::kNone) << f.record;
    EXPECT_EQ(d.id, f.id) << f.record;
    EXPECT_EQ(d.extended, f.extended) << f.record;
    EXPECT_EQ(d.rtr, f.rtr) << f.record;
    if (!f.rtr) {
      ASSERT_EQ(d.len, f.data.size()) << f.record;
      for (std::size_t i = 0; i < f.data.size(); ++i) EXPECT_EQ(d.data[i], f.data[i]) << f.record;
    }
    if (f.check != "both") continue;
    EXPECT_EQ(EncodeSlcanFrame(d), f.record + "\r");
  }
}

TEST(SlcanFramingTest, BadRecordsAreRefusedByKind) {
  const test::SlcanGolden g = test::ReadSlcanGolden();
  ASSERT_GE(g.bad.size(), 6u);
  for (const test::SlcanGoldenBad& b : g.bad) {
    CanFrame d;
    d.id = 0x55;
    EXPECT_STREQ(ErrorName(DecodeSlcanFrame(b.record, d)), b.error.c_str()) << b.record;
    EXPECT_EQ(d.id, 0x55u) << "a refused record leaves the frame alone: " << b.record;
  }
}

TEST(SlcanFramingTest, OverlongRecordsAreDroppedAndCountedFromTheirFirstByteOverTheLimit) {
  SlcanAdapter a;
  std::string reply;
  std::vector<CanFrame> frames;
  a.OnHostBytes(Time{}, std::string(40, '1'), reply, frames);
  EXPECT_EQ(a.overlong_records(), 1u) << "counted before its CR comes";
  a.OnHostBytes(Time{}, "\rV\r", reply, frames);
  EXPECT_EQ(a.overlong_records(), 1u);
  EXPECT_EQ(a.counters().records, 1u) << "only V is a record";
}

TEST(SlcanAdapterTest, GoldenSessionAnswersAsTheAdapter) {
  const test::SlcanGolden g = test::ReadSlcanGolden();
  ASSERT_GE(g.session.size(), 15u);
  SlcanAdapter a;
  std::vector<CanFrame> on_bus;
  for (const test::SlcanGoldenExchange& x : g.session) {
    std::string reply;
    a.OnHostBytes(TimeFromNs(1000), x.host, reply, on_bus);
    EXPECT_EQ(reply, x.reply) << "host sent " << test::SlcanUnescape(x.host);
  }
  ASSERT_EQ(on_bus.size(), 2u) << "the T and t records of the open channel";
  EXPECT_EQ(on_bus[0].id, 0x0CAD1C80u);
  EXPECT_TRUE(on_bus[0].extended);
  EXPECT_EQ(on_bus[0].t, TimeFromNs(1000));
  EXPECT_EQ(on_bus[1].id, 0x123u);
  EXPECT_EQ(a.bitrate_bps(), 250000);
  EXPECT_EQ(a.counters().refused, 5u);
  EXPECT_FALSE(a.open());
}

TEST(SlcanAdapterTest, BusFramesReachTheHostOnlyWhileOpenWithTimeStampsOnRequest) {
  SlcanAdapter a;
  CanFrame f;
  f.t = TimeFromNs(61'234'000'000);  // 61.234 s: stamp 1234 ms (mod 60000)
  f.id = 0x0CACFF1C;
  f.extended = true;
  f.len = 1;
  f.data[0] = 0xAB;
  EXPECT_EQ(a.ToHost(f), "");
  EXPECT_EQ(a.counters().dropped_closed, 1u);
  std::string reply;
  std::vector<CanFrame> frames;
  a.OnHostBytes(Time{}, "O\r", reply, frames);
  EXPECT_EQ(a.ToHost(f), "T0CACFF1C1AB\r");
  a.OnHostBytes(Time{}, "C\rZ1\rO\r", reply, frames);
  EXPECT_EQ(a.ToHost(f), "T0CACFF1C1AB04D2\r");
  EXPECT_EQ(a.counters().frames_to_host, 2u);
}

}  // namespace
}  // namespace hil::link

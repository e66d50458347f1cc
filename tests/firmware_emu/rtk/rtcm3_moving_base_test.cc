// RTCM 3 4072.0 (the moving base's antenna position; our layout, rtcm3_moving_base.h): its bits
// where the layout puts them, a round trip at the 0.1 mm resolution, its frame through the
// stream parser, and the bodies the decoder refuses.
#include "hil/firmware_emu/rtk/rtcm3_moving_base.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_stream.h"

namespace hil::rtcm3 {
namespace {

MovingBasePvt Karaj() {
  MovingBasePvt p;
  p.station_id = 17;
  p.epoch_ms = 288000200;
  p.antenna_E_m = Eigen::Vector3d(3290123.45678, 4005678.12344, 3680123.98766);
  return p;
}

TEST(Rtcm3MovingBase, FieldsWhereTheLayoutPutsThem) {
  const std::string body = Encode4072Pvt(Karaj());
  ASSERT_EQ(body.size(), kMovingBasePvtBytes);
  BitReader r(body);
  EXPECT_EQ(r.GetUnsigned(12), 4072U);
  EXPECT_EQ(r.GetUnsigned(12), 0U);  // sub-type
  EXPECT_EQ(r.GetUnsigned(12), 17U);
  EXPECT_EQ(r.GetUnsigned(30), 288000200U);
  EXPECT_EQ(r.GetSigned(38), 32901234568);  // 0.1 mm, rounded
  EXPECT_EQ(r.GetSigned(38), 40056781234);
  EXPECT_EQ(r.GetSigned(38), 36801239877);
  EXPECT_EQ(r.position(), 180U);
  EXPECT_EQ(r.GetUnsigned(4), 0U) << "padding";
}

TEST(Rtcm3MovingBase, RoundTripAtTheResolution) {
  const MovingBasePvt in = Karaj();
  const MovingBasePvt out = Decode4072Pvt(Encode4072Pvt(in));
  EXPECT_EQ(out.station_id, in.station_id);
  EXPECT_EQ(out.epoch_ms, in.epoch_ms);
  EXPECT_LE((out.antenna_E_m - in.antenna_E_m).cwiseAbs().maxCoeff(), 0.00005);
}

TEST(Rtcm3MovingBase, FrameThroughTheStreamParser) {
  const std::string frame = Frame(Encode4072Pvt(Karaj()));
  StreamParser p;
  std::vector<ReceivedFrame> got;
  for (const char c : frame) p.Feed(c, got);
  ASSERT_EQ(got.size(), 1U);
  EXPECT_FALSE(got[0].crc_failed);
  EXPECT_EQ(got[0].message_number(), 4072);
  EXPECT_EQ(Subtype4072(got[0].body), 0);
  EXPECT_EQ(Decode4072Pvt(got[0].body).station_id, 17);
}

TEST(Rtcm3MovingBase, RefusesOtherBodies) {
  std::string body = Encode4072Pvt(Karaj());
  EXPECT_THROW(Decode4072Pvt(body.substr(0, 20)), std::invalid_argument);
  BitWriter other;
  other.PutUnsigned(4072, 12);
  other.PutUnsigned(1, 12);  // 4072.1
  EXPECT_EQ(Subtype4072(other.bytes()), 1);
  EXPECT_THROW(Decode4072Pvt(other.bytes()), std::invalid_argument);
  EXPECT_EQ(Subtype4072(std::string("\x3E\xD0\x00", 3)), -1) << "a 1005 is not a 4072";
  MovingBasePvt bad = Karaj();
  bad.station_id = 4096;
  EXPECT_THROW(Encode4072Pvt(bad), std::out_of_range);
}

}  // namespace
}  // namespace hil::rtcm3

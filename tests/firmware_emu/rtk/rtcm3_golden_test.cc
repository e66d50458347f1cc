// Golden RTCM 3 streams of the emulated base (vectors/rtcm3/): 60 s at 1 Hz of the Karaj base,
// MSM7 with 1006 and MSM4 with 1005, byte for byte (HIL_REGEN_VECTORS=1 rewrites them). Each
// golden is also split back into frames here: no CRC error, no stray byte, the expected messages.
#include <map>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include "golden_file.h"
#include "rtk_base_fixture.h"

namespace hil::rtk {
namespace {

void CheckGolden(rtcm3::MsmKind kind, int station_message, const std::string& file) {
  RtkBaseConfig c = test::KarajBase(kind);
  c.station_message = station_message;
  const std::string stream = test::BaseStream(c, 60, 1);
  hil::test::CheckOrWriteGolden("vectors/rtcm3/" + file, stream);
  const rtcm3::SplitResult r = rtcm3::Split(stream);
  EXPECT_EQ(r.crc_errors, 0U);
  EXPECT_EQ(r.skipped_bytes, 0U);
  std::map<int, int> count;
  for (const auto& b : r.bodies) ++count[rtcm3::MessageNumber(b)];
  EXPECT_EQ(count[1070 + static_cast<int>(kind)], 60);
  EXPECT_EQ(count[station_message], 6);
}

TEST(Rtcm3Golden, BaseMsm7With1006) {
  CheckGolden(rtcm3::MsmKind::kMsm7, 1006, "base_msm7_1006_60s.rtcm3");
}
TEST(Rtcm3Golden, BaseMsm4With1005) {
  CheckGolden(rtcm3::MsmKind::kMsm4, 1005, "base_msm4_1005_60s.rtcm3");
}

}  // namespace
}  // namespace hil::rtk

#include "hil/harness/dut/n2k_bus_reader.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/outputs/n2k_encoder.h"

namespace hil::harness {
namespace {

namespace out = estimator::outputs;

std::optional<EstimateRecord> Feed(N2kBusReader& r, const out::CanFrame& f) {
  return r.Frame(f.id, std::string_view(reinterpret_cast<const char*>(f.data.data()), f.len),
                 WallTimeFromNs(42));
}

// navd's frames of one solution, in navd's order (rapid group, then the 129029 fast packet)
TEST(N2kBusReaderTest, RecordFrom129029WithVelocityAndHeadingOfTheSameSid) {
  const UnixTime start_utc = UnixTimeFromNs(1370851200LL * 1000000000LL);  // 2013-06-10T08:00:00Z
  const std::uint16_t days = static_cast<std::uint16_t>(1370851200LL / 86400);
  const double sod = static_cast<double>(1370851200LL % 86400) + 12.5;
  N2kBusReader r(start_utc);
  const std::uint8_t sid = 9;
  EXPECT_FALSE(Feed(r, out::EncodePositionRapid(35.48, 50.6, 0x80)));
  EXPECT_FALSE(Feed(r, out::EncodeCogSogRapid(sid, M_PI / 6, 1.0, 0x80)));
  EXPECT_FALSE(Feed(r, out::EncodeVesselHeading(sid, M_PI / 6, 0x80)));
  EXPECT_FALSE(Feed(r, out::EncodeAttitude(sid, M_PI / 6, 0.01, -0.02, 0x80)));
  const auto fp =
      out::EncodeGnssPosition(sid, days, sod, 35.4796096, 50.5979765, 1312.25, 1, 8, 1.0, 2, 0x80);
  std::optional<EstimateRecord> rec;
  for (int i = 0; i < fp.count; ++i) rec = Feed(r, fp.frames[static_cast<std::size_t>(i)]);
  ASSERT_TRUE(rec);
  EXPECT_NEAR(ToSeconds(rec->t_validity), 12.5, 1e-4);
  EXPECT_NEAR(rec->lat_deg, 35.4796096, 1e-12);
  EXPECT_NEAR(rec->lon_deg, 50.5979765, 1e-12);
  EXPECT_NEAR(rec->height_m, 1312.25, 1e-6);
  ASSERT_TRUE(rec->vel_enu_mps);
  EXPECT_NEAR(rec->vel_enu_mps->x(), 0.5, 1e-3);
  EXPECT_NEAR(rec->vel_enu_mps->y(), std::sqrt(3.0) / 2, 1e-3);
  ASSERT_TRUE(rec->yaw_deg);
  EXPECT_NEAR(*rec->yaw_deg, 30.0, 0.01);
  EXPECT_EQ(rec->wall_rx, WallTimeFromNs(42));
  EXPECT_EQ(r.frames_per_pgn().at(129029), 7u);
  EXPECT_EQ(r.frames_per_pgn().at(129025), 1u);
  EXPECT_EQ(r.frames_per_pgn().at(127257), 1u);

  // another SID: the 129029 stands alone (no stale velocity or heading)
  const auto fp2 =
      out::EncodeGnssPosition(sid + 1, days, sod + 1, 35.4796, 50.5979, 1312.0, 1, 8, 1.0, 3, 0x80);
  for (int i = 0; i < fp2.count; ++i) rec = Feed(r, fp2.frames[static_cast<std::size_t>(i)]);
  ASSERT_TRUE(rec);
  EXPECT_FALSE(rec->vel_enu_mps);
  EXPECT_FALSE(rec->yaw_deg);
}

}  // namespace
}  // namespace hil::harness

// A decoded NMEA epoch as a filter sample: UTC → GPS time, the configured accuracy model and the
// RMC velocity.
#include "hil/estimator/drivers/nmea_gnss_sample.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

TEST(NmeaGnssSampleTest, MapsTimeAccuracyAndVelocity) {
  // GIVEN a GGA + RMC epoch at 2012-07-04T19:14:34Z, HDOP 1.2, 8 satellites, 2 m/s at 90° (east)
  NmeaMeasurement m;
  m.tov_unix_ns = 1341429274LL * kNsPerSecond + 500'000'000;
  m.lat_deg = 35.5;
  m.lon_deg = 50.6;
  m.height_m = 1300.25;
  m.quality = 1;
  m.num_sv = 8;
  m.hdop = 1.2;
  m.speed_mps = 2.0;
  m.course_deg = 90.0;
  NmeaAccuracy acc;
  acc.uere_m = 3.0;
  acc.velocity_std_mps = 0.3;
  // WHEN it becomes a sample with GPS − UTC = 16 s (2012)
  const GnssSample g = ToGnssSample(m, 16, acc);
  // THEN its time is GPS time: UTC + 16 s, counted from 1980-01-06
  EXPECT_EQ(ToNs(g.t), (1341429274LL - kGpsEpochUnix_s + 16) * kNsPerSecond + 500'000'000);
  EXPECT_EQ(UnixNsFromGpsTime(g.t, 16), m.tov_unix_ns);
  EXPECT_DOUBLE_EQ(g.position.lat_deg, 35.5);
  EXPECT_DOUBLE_EQ(g.position.lon_deg, 50.6);
  EXPECT_DOUBLE_EQ(g.position.height_m, 1300.25);
  // AND 1σ = HDOP × UERE / √2 per horizontal axis, twice that vertically
  const double h = 1.2 * 3.0 / std::sqrt(2.0);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.x(), h);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.y(), h);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.z(), 2 * h);
  EXPECT_EQ(g.num_sv, 8);
  EXPECT_EQ(g.fix_quality, 1);
  EXPECT_DOUBLE_EQ(g.hdop, 1.2);
  // AND the RMC course and speed give the ENU velocity with the configured 1σ
  ASSERT_TRUE(g.has_velocity);
  EXPECT_NEAR(g.vel_enu_mps.x(), 2.0, 1e-12);
  EXPECT_NEAR(g.vel_enu_mps.y(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(g.vel_enu_mps.z(), 0.0);
  EXPECT_DOUBLE_EQ(g.vel_std_enu_mps.x(), 0.3);
  EXPECT_DOUBLE_EQ(g.vel_std_enu_mps.z(), 0.6);
  // AND that σ is marked as the configured figure, not the receiver's (RMC has no accuracy)
  EXPECT_TRUE(g.vel_std_configured);
}

TEST(NmeaGnssSampleTest, RtkFixUsesItsOwnSigmaAndNoRmcMeansNoVelocity) {
  NmeaMeasurement m;
  m.quality = kGgaQualityRtkFixed;
  m.hdop = 0.9;
  NmeaAccuracy acc;
  acc.rtk_fixed_std_m = 0.02;
  const GnssSample g = ToGnssSample(m, 18, acc);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.x(), 0.02);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.z(), 0.04);
  EXPECT_FALSE(g.has_velocity);
  // a missing HDOP counts as 5 for a GPS fix, and is reported as 0
  m.quality = 1;
  m.hdop.reset();
  const GnssSample n = ToGnssSample(m, 18, NmeaAccuracy{});
  EXPECT_DOUBLE_EQ(n.pos_std_enu_m.x(), 5.0 * 2.5 / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(n.hdop, 0.0);
}

// issue 39: GGA often writes the altitude to 0.1 m. A parked receiver's height then sits in one
// step or the next, 10 cm apart; with a 1 cm vertical σ every other fix was rejected. The
// rounding's uniform error (variance step²/12) is part of the fix's vertical σ.
TEST(NmeaGnssSampleTest, AltitudeRoundingWidensTheVerticalSigma) {
  NmeaMeasurement m;
  m.quality = kGgaQualityRtkFixed;
  NmeaAccuracy acc;
  acc.rtk_fixed_std_m = 0.005;
  m.altitude_step_m = 0.1;
  const GnssSample g = ToGnssSample(m, 18, acc);
  EXPECT_DOUBLE_EQ(g.pos_std_enu_m.x(), 0.005);
  EXPECT_NEAR(g.pos_std_enu_m.z(), std::sqrt(0.01 * 0.01 + 0.1 * 0.1 / 12.0), 1e-12);
  m.altitude_step_m = 0.0001;  // four decimals: the rounding is negligible
  EXPECT_NEAR(ToGnssSample(m, 18, acc).pos_std_enu_m.z(), 0.01, 1e-6);
}

// issue 39: GGA's height is its altitude plus the geoid separation, both rounded (0.1 m). The
// separation's rounding is one offset for the site, the same in every fix (+4.3 cm on the tractor
// rig's site, 11.657 m written 11.7): not a noise of the fix but an error of the height that no fix
// reveals, carried as its own σ (uniform over the step) and not in the fix's noise.
TEST(NmeaGnssSampleTest, GeoidSeparationRoundingIsACommonHeightErrorAndVdopIsPassedOn) {
  NmeaMeasurement m;
  m.quality = kGgaQualityRtkFixed;
  NmeaAccuracy acc;
  acc.rtk_fixed_std_m = 0.005;
  m.altitude_step_m = 0.1;
  m.geoid_separation_m = 11.7;
  m.geoid_step_m = 0.1;
  m.vdop = 6.31;
  const GnssSample g = ToGnssSample(m, 18, acc);
  EXPECT_NEAR(g.height_datum_std_m, 0.1 / std::sqrt(12.0), 1e-12);
  EXPECT_NEAR(g.pos_std_enu_m.z(), std::sqrt(0.01 * 0.01 + 0.1 * 0.1 / 12.0), 1e-12);
  EXPECT_DOUBLE_EQ(g.vdop, 6.31);
  m.geoid_step_m = 0.0;  // no separation written
  m.vdop.reset();
  EXPECT_EQ(ToGnssSample(m, 18, acc).height_datum_std_m, 0.0);
  EXPECT_EQ(ToGnssSample(m, 18, acc).vdop, 0.0);
}

}  // namespace
}  // namespace hil::estimator::drivers

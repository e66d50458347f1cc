#include "hil/firmware_emu/gnss/constellation.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"

namespace hil::gnss {
namespace {

double GpsSeconds(const char* iso) {
  const GpsWeekTime g = GpsFrom(ParseIsoUtc(iso));
  return g.week * 604800.0 + g.tow_s();
}

TEST(ConstellationTest, SkyStatisticsLookLikeGps) {
  const Constellation c(1);
  const double t0 = GpsSeconds("2013-06-10T00:00:00Z");
  double hdop = 0, vdop = 0;
  int n = 0, min_used = 99, max_used = 0;
  for (double t = 0; t < 86400; t += 300) {
    const auto sky = c.Sky(t0 + t, 35.48, 50.60, 1312, SkyConditions{});
    int used = 0;
    for (const auto& s : sky) used += s.used ? 1 : 0;
    min_used = std::min(min_used, used);
    max_used = std::max(max_used, used);
    const Dops d = ComputeDops(sky);
    ASSERT_TRUE(d.valid);
    hdop += d.hdop, vdop += d.vdop, ++n;
  }
  EXPECT_GE(min_used, 5);
  EXPECT_LE(max_used, 14);
  EXPECT_GT(hdop / n, 0.7);
  EXPECT_LT(hdop / n, 1.6);
  EXPECT_LT(vdop / n, 2.8);
  std::printf("used %d..%d, mean HDOP %.2f, mean VDOP %.2f\n", min_used, max_used, hdop / n,
              vdop / n);
}

TEST(ConstellationTest, GeometryChangesWithTimeAndPlaceAndRepeatsAfterASiderealDay) {
  const Constellation c(1);
  const double t0 = GpsSeconds("2013-06-10T08:00:00Z");
  const auto a = c.Sky(t0, 35.48, 50.60, 1312, SkyConditions{});
  const auto b = c.Sky(t0 + 600, 35.48, 50.60, 1312, SkyConditions{});
  const auto d =
      c.Sky(t0 + 86164.0905, 35.48, 50.60, 1312, SkyConditions{});  // 2 orbits = 1 sidereal day
  const auto south = c.Sky(t0, -33.87, -70.67, 500, SkyConditions{});
  ASSERT_FALSE(a.empty());
  const SatelliteView& s0 = a.front();
  bool moved = false, repeated = false;
  for (const auto& s : b) {
    if (s.svid == s0.svid)
      moved = std::abs(s.elev_deg - s0.elev_deg) > 1.0 || std::abs(s.azim_deg - s0.azim_deg) > 1.0;
  }
  for (const auto& s : d) {
    if (s.svid == s0.svid) repeated = std::abs(s.elev_deg - s0.elev_deg) < 1.0;
  }
  EXPECT_TRUE(moved);
  EXPECT_TRUE(repeated);
  EXPECT_NE(a.size() == south.size() && a.front().svid == south.front().svid, true);
  for (const auto& s : a) {
    EXPECT_GE(s.elev_deg, 0.0);
    EXPECT_GE(s.azim_deg, 0.0);
    EXPECT_LT(s.azim_deg, 360.0);
    if (s.tracked) {
      EXPECT_GT(s.cno_dbhz, 25);
    }
  }
}

TEST(ConstellationTest, BlockedSkyAndMaskRemoveSatellites) {
  const Constellation c(1);
  const double t0 = GpsSeconds("2013-06-10T08:00:00Z");
  SkyConditions blocked;
  blocked.sky_blocked = true;
  for (const auto& s : c.Sky(t0, 35.48, 50.60, 1312, blocked)) EXPECT_FALSE(s.tracked);
  SkyConditions high;
  high.elevation_mask_deg = 30;
  for (const auto& s : c.Sky(t0, 35.48, 50.60, 1312, high)) {
    if (s.used) {
      EXPECT_GE(s.elev_deg, 30.0);
    }
  }
}

// IS-GPS-200 §20.3.3.4.3 (Table 20-IV) with e = 0 and no harmonic corrections, as an RTK engine
// computes a satellite from its broadcast ephemeris (written here from the specification).
Eigen::Vector3d IsGpsPosition(const GpsEphemeris& e, double gps_s) {
  constexpr double kMu = 3.986005e14, kOmegaE = 7.2921151467e-5;
  const double a = e.sqrt_a * e.sqrt_a;
  const double tk = gps_s - (e.week * 604800.0 + e.toe_s);
  const double u = e.m0_rad + std::sqrt(kMu / (a * a * a)) * tk;
  const double node = e.omega0_rad - kOmegaE * (tk + e.toe_s);
  const double x = a * std::cos(u), y = a * std::sin(u);
  return {x * std::cos(node) - y * std::cos(e.i0_rad) * std::sin(node),
          x * std::sin(node) + y * std::cos(e.i0_rad) * std::cos(node), y * std::sin(e.i0_rad)};
}

TEST(ConstellationTest, BroadcastEphemerisGivesOurPositions) {
  const Constellation c(1);
  const double toe = GpsSeconds("2026-06-10T08:00:00Z");
  double worst_m = 0;
  for (std::size_t i = 0; i < c.gps_count(); ++i) {
    const GpsEphemeris e = c.Ephemeris(i, toe);
    EXPECT_EQ(e.svid, c.GpsPositionEcef(i, toe).svid);
    EXPECT_GE(e.toe_s, 0.0);
    EXPECT_LT(e.toe_s, 604800.0);
    for (double dt = -7200; dt <= 7200; dt += 600) {
      const Eigen::Vector3d ours = c.GpsPositionEcef(i, toe + dt).p_E_m;
      worst_m = std::max(worst_m, (IsGpsPosition(e, toe + dt) - ours).norm());
    }
  }
  // the two computations differ only by rounding (26 560 km orbits: a few µm of 1e-16)
  EXPECT_LT(worst_m, 1e-3);
  RecordProperty("worst_ephemeris_error_m", std::to_string(worst_m));
}

}  // namespace
}  // namespace hil::gnss

#include "hil/estimator/geodesy.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

// LlaFromEcef inverts the closed-form EcefFromLla: latitude to 1e-11 ° (about 1 µm), height to 1
// µm, from 500 m below the ellipsoid to 100 km above it, at every latitude off the poles
TEST(Geodesy, LlaFromEcefInvertsEcefFromLla) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> lat(-89.99, 89.99), lon(-180.0, 180.0), h(-500.0, 1e5);
  double worst_lat = 0, worst_h = 0;
  for (int k = 0; k < 100000; ++k) {
    const Lla g{lat(rng), lon(rng), k % 2 ? h(rng) : h(rng) * 1e-3};
    const Lla back = LlaFromEcef(EcefFromLla(g));
    worst_lat = std::max(worst_lat, std::abs(back.lat_deg - g.lat_deg));
    worst_h = std::max(worst_h, std::abs(back.height_m - g.height_m));
    ASSERT_NEAR(std::remainder(back.lon_deg - g.lon_deg, 360.0), 0.0, 1e-11);
  }
  EXPECT_LT(worst_lat, 1e-11);
  EXPECT_LT(worst_h, 1e-6);
}

TEST(Geodesy, PolesAndEquator) {
  const Lla north = LlaFromEcef(EcefFromLla({90.0, 0.0, 12.0}));
  EXPECT_DOUBLE_EQ(north.lat_deg, 90.0);
  EXPECT_NEAR(north.height_m, 12.0, 1e-6);
  const Lla south = LlaFromEcef(EcefFromLla({-90.0, 10.0, -3.0}));
  EXPECT_DOUBLE_EQ(south.lat_deg, -90.0);
  EXPECT_NEAR(south.height_m, -3.0, 1e-6);
  const Lla eq = LlaFromEcef(EcefFromLla({0.0, 45.0, 100.0}));
  EXPECT_NEAR(eq.lat_deg, 0.0, 1e-12);
  EXPECT_NEAR(eq.lon_deg, 45.0, 1e-12);
  EXPECT_NEAR(eq.height_m, 100.0, 1e-6);
}

}  // namespace
}  // namespace hil::estimator

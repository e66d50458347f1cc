// The signal model of the sky's obstructions: C/N0, code and carrier multipath of one satellite,
// and the position error the used satellites' range errors make (consistent with the DOPs).
#include "hil/firmware_emu/gnss/sky_shading.h"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace hil::gnss {
namespace {

ShadingConfig WithObstacles(std::vector<world::SkyObstacle> obstacles) {
  ShadingConfig c;
  c.obstructions = std::make_shared<world::SkyObstructions>(std::move(obstacles));
  return c;
}

world::SkyObstacle Wall(double amplitude, bool opaque) {
  // a face at north 10 m facing south, 40 m long, 10 m tall
  world::SkyObstacle o;
  o.kind = world::SkyObstacleKind::kBuilding;
  o.footprint = {{0, 15}, {20, 5}, 0};
  o.height_m = 10;
  o.opaque = opaque;
  o.loss_db = opaque ? 0 : 6;
  o.max_loss_db = 40;
  o.reflection_amplitude = amplitude;
  return o;
}

TEST(SkyShading, OpenSkyChangesNothing) {
  const SignalEffect fx = ShadeSignal(ShadingConfig{}, {0, 0, 2}, 45, 30);
  EXPECT_EQ(fx.cno_change_db, 0.0);
  EXPECT_EQ(fx.code_error_m, 0.0);
  EXPECT_FALSE(fx.nlos);
}

TEST(SkyShading, BlockedSatelliteWithoutAReflectionIsLost) {
  // due north at 10°: the building is in the way, and its faces reflect nothing from the north
  const SignalEffect fx = ShadeSignal(WithObstacles({Wall(0.5, true)}), {0, 0, 2}, 0, 10);
  EXPECT_TRUE(std::isinf(fx.cno_change_db));
  EXPECT_LT(fx.cno_change_db, 0.0);
}

TEST(SkyShading, BlockedSatelliteWithAReflectionIsNlosWithTheExcessPathAsItsError) {
  // a second building south of the antenna, its face y = −10 looking north: the satellite due
  // north at 10° is blocked by the first and reflected off the second, excess 2·10·cos 10°
  world::SkyObstacle south = Wall(0.5, true);
  south.footprint.centre_m = {0, -15};
  const SignalEffect fx = ShadeSignal(WithObstacles({Wall(0.5, true), south}), {0, 0, 2}, 0, 10);
  EXPECT_TRUE(fx.nlos);
  EXPECT_NEAR(fx.code_error_m, 20 * std::cos(10 * std::numbers::pi / 180), 1e-9);
  EXPECT_NEAR(fx.carrier_error_m, fx.code_error_m, 1e-12);
  EXPECT_NEAR(fx.cno_change_db, 20 * std::log10(0.5), 1e-9);
}

TEST(SkyShading, LineOfSightMultipathStaysWithinTheTwoPathEnvelope) {
  const ShadingConfig c = WithObstacles({Wall(0.3, false)});
  // satellites due south at 5…60°: direct clear, reflection off the south-facing face
  for (double el = 5; el <= 60; el += 0.37) {
    const SignalEffect fx = ShadeSignal(c, {0, 0, 2}, 180, el);
    const double delta = 2 * 10 * std::cos(el * std::numbers::pi / 180);
    if (2 + 10 * std::tan(el * std::numbers::pi / 180) > 10) {
      EXPECT_EQ(fx.code_error_m, 0.0) << el;  // the mirror point is above the roof
      continue;
    }
    EXPECT_FALSE(fx.nlos);
    EXPECT_LE(std::abs(fx.code_error_m), 0.3 * delta / (1 - 0.3) + 1e-9) << el;
    EXPECT_LE(std::abs(fx.carrier_error_m), kGpsL1Wavelength_m / 4) << el;
    // C/N0 between destructive and constructive interference: 20·log10(1 ∓ 0.3)
    EXPECT_GE(fx.cno_change_db, 20 * std::log10(0.7) - 1e-9);
    EXPECT_LE(fx.cno_change_db, 20 * std::log10(1.3) + 1e-9);
  }
}

std::vector<SatelliteView> Sky() {
  std::vector<SatelliteView> s;
  const double az[] = {0, 70, 140, 210, 280, 35, 250};
  const double el[] = {15, 40, 25, 60, 30, 75, 10};
  for (int i = 0; i < 7; ++i) {
    SatelliteView v;
    v.svid = i + 1;
    v.azim_deg = az[i];
    v.elev_deg = el[i];
    v.used = true;
    s.push_back(v);
  }
  return s;
}

TEST(SkyShading, ACommonRangeErrorIsClockAndLeavesNoResidual) {
  const auto sats = Sky();
  const RangeErrorSolution sol = SolveRangeErrors(sats, std::vector<double>(sats.size(), 5.0));
  ASSERT_TRUE(sol.valid);
  EXPECT_LT(sol.dp_N_m.norm(), 1e-9);
  EXPECT_LT(sol.sigma_m, 1e-9);
}

TEST(SkyShading, OneSatellitesErrorMovesThePositionByTheGeometrysGain) {
  auto sats = Sky();
  sats[6].used = false;  // unused satellites do not count
  std::vector<double> err(sats.size(), 0.0);
  err[0] = 1.0;  // 1 m on the northern satellite at 15°
  err[6] = 50.0;
  const RangeErrorSolution sol = SolveRangeErrors(sats, err);
  // the same least squares by hand: (HᵀH)⁻¹Hᵀe; ‖dx‖² summed over unit errors on every satellite
  // is PDOP² + TDOP² (what DOP means)
  Eigen::MatrixXd h(6, 4);
  for (int i = 0; i < 6; ++i) {
    const double e = sats[i].elev_deg * std::numbers::pi / 180;
    const double a = sats[i].azim_deg * std::numbers::pi / 180;
    h.row(i) << -std::cos(e) * std::sin(a), -std::cos(e) * std::cos(a), -std::sin(e), 1.0;
  }
  const Eigen::MatrixXd g = (h.transpose() * h).inverse() * h.transpose();
  EXPECT_NEAR(sol.dp_N_m.x(), g(0, 0), 1e-9);
  EXPECT_NEAR(sol.dp_N_m.y(), g(1, 0), 1e-9);
  EXPECT_NEAR(sol.dp_N_m.z(), g(2, 0), 1e-9);
  EXPECT_LT(sol.dp_N_m.y(), 0.0);  // a long range to the north pulls the fix south
  EXPECT_EQ(sol.residual_m[6], 0.0);
  EXPECT_GT(sol.sigma_m, 0.0);
}

}  // namespace
}  // namespace hil::gnss

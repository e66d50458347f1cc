#include "hil/truth/truth_integrator.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "truth_test_scenarios.h"

namespace hil::truth {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

TEST(TruthIntegratorTest, StraightLineAtConstantSpeedHasZeroBodyRate) {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1300};
  c.heading_deg = 90;  // east
  c.speed_mps = 1.6 / 3.6;
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  for (double t : {1.0, 50.0, 100.0}) {
    const TruthSample s = truth.Sample(TimeFromSeconds(t));
    EXPECT_NEAR(s.p_NB_N_m.x(), t * c.speed_mps, 1e-6);
    EXPECT_NEAR(s.p_NB_N_m.y(), 0, 1e-9);
    EXPECT_NEAR(s.w_IB_B_radps.norm(), 0, 1e-12);
    EXPECT_NEAR(s.w_NB_B_radps.norm(), 0, 1e-12);
    // unaccelerated: the accelerometer reads minus gravity (whose direction in N tilts by
    // distance / Earth radius away from the origin, 7e-6 rad here)
    EXPECT_NEAR((s.q_NB * s.f_B_mps2 + s.gravity_N_mps2).norm(), 0, 1e-9);
    EXPECT_NEAR(s.f_B_mps2.z(), s.gravity_N_mps2.norm(), 1e-8);
    EXPECT_NEAR(s.wheel_speed_left_mps, c.speed_mps, 1e-12);
    EXPECT_NEAR(s.wheel_speed_right_mps, c.speed_mps, 1e-12);
  }
}

TEST(TruthIntegratorTest, SpeedVariationIsARepeatableGaussMarkovAroundTheCommand) {
  SpeedVariation a(0.03, 5.0, 11), b(0.03, 5.0, 11), other(0.03, 5.0, 12);
  // the same function of time whatever the order of evaluation
  const double late = a.Factor(500.05);
  EXPECT_DOUBLE_EQ(b.Factor(3.3), a.Factor(3.3));
  EXPECT_DOUBLE_EQ(b.Factor(500.05), late);
  EXPECT_NE(other.Factor(3.3), a.Factor(3.3));
  EXPECT_DOUBLE_EQ(SpeedVariation(0, 5, 1).Factor(10), 1.0);
  // statistics over 20 000 s: standard deviation 3 % and lag correlation exp(-1) at one tau
  double sum = 0, sum2 = 0, lag = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = a.Factor(i * 0.1) - 1, y = a.Factor(i * 0.1 + 5.0) - 1;
    sum += x, sum2 += x * x, lag += x * y;
  }
  const double var = sum2 / n - (sum / n) * (sum / n);
  EXPECT_NEAR(std::sqrt(var), 0.03, 0.003);
  EXPECT_NEAR(lag / n / var, std::exp(-1.0), 0.05);
  // in the vehicle: the speed follows the varied command, the mean stays the commanded speed
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1300};
  c.heading_deg = 90;
  c.speed_mps = 1.0;
  c.vehicle.speed_variation_std = 0.05;
  TruthIntegrator truth(c);
  double vmin = 10, vmax = 0;
  for (int k = 1; k <= 600; ++k) {
    const double v = truth.Sample(TimeFromSeconds(k * 0.5)).speed_mps;
    vmin = std::min(vmin, v), vmax = std::max(vmax, v);
  }
  EXPECT_LT(vmin, 0.97);
  EXPECT_GT(vmax, 1.03);
  const double e = truth.Sample(TimeFromSeconds(300)).p_NB_N_m.x();
  EXPECT_NEAR(e / 300.0, 1.0, 0.05) << "travelled at about the commanded speed";
}

TEST(TruthIntegratorTest, ConstantSteeringGivesCircleOfRadiusLOverTanDelta) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.heading_deg = 0;
  c.speed_mps = 1.0;
  c.steer_deg = 20;
  c.vehicle.wheelbase_m = 0.84;
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const double R = c.vehicle.wheelbase_m / std::tan(20 * kDeg);
  // centre of the circle: to the left (west) of a northbound start
  const Eigen::Vector2d centre(-R, 0);
  for (double t = 1; t < 30; t += 3.7) {
    const TruthSample s = truth.Sample(TimeFromSeconds(t));
    EXPECT_NEAR((s.p_NB_N_m.head<2>() - centre).norm(), R, 1e-7) << "t=" << t;
    // centripetal specific force v²/R to the left (body +y), yaw rate v/R
    const Eigen::Vector3d a_N = s.q_NB * s.f_B_mps2 + s.gravity_N_mps2;
    EXPECT_NEAR(a_N.norm(), 1.0 / R, 1e-7);
    EXPECT_NEAR(a_N.head<2>().normalized().dot((centre - s.p_NB_N_m.head<2>()).normalized()), 1,
                1e-9);
    EXPECT_NEAR(s.f_B_mps2.y(), 1.0 / R, 1e-5);  // plus gravity's tilt (3.6e-7 rad at 2.3 m)
    EXPECT_NEAR(s.w_NB_B_radps.z(), 1.0 / R, 1e-9);
    EXPECT_NEAR(s.steer_rad, 20 * kDeg, 1e-12);
    // inner (left) wheel slower than the outer
    EXPECT_NEAR(s.wheel_speed_right_mps - s.wheel_speed_left_mps, c.vehicle.track_m / R, 1e-9);
  }
}

TEST(TruthIntegratorTest, DiffDriveTurnsInPlaceAtConstantYawRate) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.vehicle = VehicleParams::DiffDrive();
  c.speed_mps = 0;
  c.yaw_rate_dps = 30;
  c.start_p_N_m = Eigen::Vector2d(3, 4);
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const TruthSample s = truth.Sample(TimeFromSeconds(7));
  EXPECT_EQ(s.p_NB_N_m.head<2>(), Eigen::Vector2d(3, 4));
  EXPECT_NEAR(s.w_NB_B_radps.z(), 30 * kDeg, 1e-12);
  EXPECT_NEAR(s.wheel_speed_right_mps, 30 * kDeg * c.vehicle.track_m / 2, 1e-12);
  EXPECT_NEAR(s.wheel_speed_left_mps, -30 * kDeg * c.vehicle.track_m / 2, 1e-12);
  // heading north at t = 0, turning left 30°/s: 210° of turn by t = 7 s
  const Eigen::Vector3d fwd = s.q_NB * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(fwd.y(), fwd.x()), (90 + 210 - 360) * kDeg, 1e-8);
}

TEST(TruthIntegratorTest, LateralSlipSwingsTheVelocityToTheOutsideOfTheTurn) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.speed_mps = 2;
  c.steer_deg = 15;
  c.vehicle.slip_gain_rad_per_mps2 = 0.02;
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const TruthSample s = truth.Sample(TimeFromSeconds(4));
  const double yaw_rate = 2 * std::tan(15 * kDeg) / c.vehicle.wheelbase_m;
  const Eigen::Vector3d v_B = s.q_NB.conjugate() * s.v_NB_N_mps;
  // β = −k v ψ̇: in a left turn the velocity points to the right of the body x axis
  EXPECT_NEAR(std::atan2(v_B.y(), v_B.x()), -0.02 * 2 * yaw_rate, 1e-9);
  EXPECT_NEAR(s.w_NB_B_radps.z(), yaw_rate, 1e-9);
  // steady state: still a circle, with acceleration v ψ̇ perpendicular to the velocity
  EXPECT_NEAR(s.a_NB_N_mps2.norm(), 2 * yaw_rate, 1e-7);
  EXPECT_NEAR(s.a_NB_N_mps2.dot(s.v_NB_N_mps), 0, 1e-7);
}

TEST(TruthIntegratorTest, EngineVibrationShowsInTheAccelerometerAndGyroTruth) {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1312};
  c.speed_mps = 0;
  c.earth_rotation = false;
  VibrationComponent v;
  v.frequency_hz = 25;
  const double w = 2 * std::numbers::pi * 25;
  v.heave_m = 0.5 / (w * w);  // 0.5 m/s² peak
  v.roll_rad = 2 * kDeg / w;  // 2 °/s peak
  c.vibration.components.push_back(v);
  TruthIntegrator truth(c);
  double f_lo = 1e9, f_hi = -1e9, w_hi = 0;
  for (int k = 0; k < 1000; ++k) {
    const TruthSample s = truth.Sample(TimeFromNs(k * 1'000'000LL + 100'000));
    const double g = s.gravity_N_mps2.norm();
    f_lo = std::min(f_lo, s.f_B_mps2.z() - g);
    f_hi = std::max(f_hi, s.f_B_mps2.z() - g);
    w_hi = std::max(w_hi, std::abs(s.w_IB_B_radps.x()));
  }
  EXPECT_NEAR(f_hi, 0.5, 0.01);
  EXPECT_NEAR(f_lo, -0.5, 0.01);
  EXPECT_NEAR(w_hi, 2 * kDeg, 1e-3 * kDeg);
}

TEST(TruthIntegratorTest, StationaryOnSlopeFeelsGravityAlongTheSlopeNormalTilt) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.speed_mps = 0;
  c.heading_deg = 30;
  c.terrain.type = TerrainConfig::Type::kPlane;
  c.terrain.slope_deg = 10;
  c.terrain.uphill_heading_deg = 30;  // facing straight uphill
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const TruthSample s = truth.Sample(TimeFromSeconds(5));
  const double g = s.gravity_N_mps2.norm();
  EXPECT_NEAR(s.f_B_mps2.norm(), g, 1e-12);
  // pitched nose-up by the slope: f = g (sin θ, 0, cos θ)
  EXPECT_NEAR(s.f_B_mps2.x(), g * std::sin(10 * kDeg), 1e-6);  // gravity's tilt in N is ~1e-7 rad
  EXPECT_NEAR(s.f_B_mps2.y(), 0, 1e-6);
  EXPECT_NEAR(s.f_B_mps2.z(), g * std::cos(10 * kDeg), 1e-6);
  // in N it is exactly minus gravity
  EXPECT_NEAR((s.q_NB * s.f_B_mps2 + s.gravity_N_mps2).norm(), 0, 1e-12);
  EXPECT_NEAR(s.w_IB_B_radps.norm(), 0, 1e-15);
  EXPECT_NEAR(s.p_NB_N_m.z(), 0, 1e-12);

  // sideways on the same slope: rolled instead, left side up when uphill is to the left
  c.heading_deg = 120;  // uphill (30°) is 90° to the left
  TruthIntegrator side(c);
  const TruthSample r = side.Sample(TimeFromSeconds(5));
  EXPECT_NEAR(r.f_B_mps2.x(), 0, 1e-6);
  EXPECT_NEAR(r.f_B_mps2.y(), g * std::sin(10 * kDeg), 1e-6);
}

TEST(TruthIntegratorTest, EarthRotationAddsEarthRateToGyroTruthAndCoriolisToSpecificForce) {
  TruthConfig c;
  c.origin = {45, 10, 0};
  c.heading_deg = 0;  // north
  c.speed_mps = 2;
  TruthIntegrator on(c);
  c.earth_rotation = false;
  TruthIntegrator off(c);
  const TruthSample a = on.Sample(TimeFromSeconds(3)), b = off.Sample(TimeFromSeconds(3));
  const double we = 7.2921150e-5;
  EXPECT_NEAR(a.w_IB_B_radps.norm(), we, 1e-12);
  // level, heading north: body (F, L, U) = (N, W, U); Ω = we (0, cos φ, sin φ) in ENU
  EXPECT_NEAR(a.w_IB_B_radps.x(), we * std::cos(45 * kDeg), 1e-9);
  EXPECT_NEAR(a.w_IB_B_radps.z(), we * std::sin(45 * kDeg), 1e-9);
  // Coriolis 2Ω×v for v north points west (body +y): the ground pushes the vehicle left to keep
  // it on its line against the deflection to the right
  EXPECT_NEAR(a.f_B_mps2.y() - b.f_B_mps2.y(), 2 * we * std::sin(45 * kDeg) * 2, 1e-9);
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
}

TEST(TruthIntegratorTest, GeodeticEcefAndLocalPositionsAgree) {
  TruthConfig c = testing::RoughTurningConfig();
  TruthIntegrator truth(c);
  const TruthSample s = truth.Sample(TimeFromSeconds(12.345));
  EXPECT_LT((truth.frame().FromGeodetic({s.lat_deg, s.lon_deg, s.height_m}) - s.p_NB_N_m).norm(),
            1e-6);
  EXPECT_LT((truth.frame().FromEcef(s.p_EB_E_m) - s.p_NB_N_m).norm(), 1e-6);
  EXPECT_NEAR(s.p_NB_N_m.z(), truth.terrain().Height(s.p_NB_N_m.head<2>()),
              1e-4);  // + vibration heave
}

TEST(TruthIntegratorTest, EarlierRequestRestartsDeterministically) {
  TruthConfig c = testing::RoughTurningConfig();
  TruthIntegrator truth(c);
  const TruthSample a = truth.Sample(TimeFromSeconds(10));
  truth.Sample(TimeFromSeconds(50));
  const TruthSample b = truth.Sample(TimeFromSeconds(10));
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
  EXPECT_EQ(a.f_B_mps2, b.f_B_mps2);
}

TEST(TruthIntegratorTest, SamplesDoNotDependOnWhichOtherTimesAreSampled) {
  // the step sequence is independent of the sensor schedule: 10 Hz and 100 Hz + 7 Hz sampling give
  // bit-identical values at common times
  TruthConfig open_loop;
  open_loop.origin = {35, 50, 0};
  open_loop.steer_deg = 3;
  open_loop.terrain.type = TerrainConfig::Type::kRough;
  for (const TruthConfig& c : {testing::RoughTurningConfig(), open_loop}) {
    TruthIntegrator slow(c), fast(c);
    std::int64_t ns_fast = 0;
    for (std::int64_t k = 0; k <= 300; ++k) {
      const std::int64_t ns = k * 100'000'000LL;
      while (ns_fast < ns) {
        fast.Sample(TimeFromNs(ns_fast));
        ns_fast += ns_fast % 3 == 0 ? 10'000'000LL : 142'857'143LL / 11;
      }
      const TruthSample a = slow.Sample(TimeFromNs(ns)), b = fast.Sample(TimeFromNs(ns));
      ASSERT_EQ(a.p_NB_N_m, b.p_NB_N_m) << "t=" << ns;
      ASSERT_EQ(a.w_IB_B_radps, b.w_IB_B_radps) << "t=" << ns;
    }
  }
}

TEST(TruthIntegratorTest, VelocityAccelerationAndRatesAreDerivativesOfPoseAndVelocity) {
  const TruthConfig c = testing::RoughTurningConfig();
  TruthIntegrator truth(c);
  const double h = 1e-4;
  for (double t : {3.0, 17.51, 33.3}) {
    const TruthSample a = truth.Sample(TimeFromSeconds(t - h));
    const TruthSample m = truth.Sample(TimeFromSeconds(t));
    const TruthSample b = truth.Sample(TimeFromSeconds(t + h));
    EXPECT_LT(((b.p_NB_N_m - a.p_NB_N_m) / (2 * h) - m.v_NB_N_mps).norm(), 1e-5) << t;
    EXPECT_LT(((b.v_NB_N_mps - a.v_NB_N_mps) / (2 * h) - m.a_NB_N_mps2).norm(), 1e-3) << t;
    const Eigen::AngleAxisd d(m.q_NB.conjugate() * b.q_NB * (a.q_NB.conjugate() * m.q_NB));
    const Eigen::Vector3d w_fd = d.angle() * d.axis() / (2 * h);
    EXPECT_LT((w_fd - m.w_NB_B_radps).norm(), 1e-4) << t;
    EXPECT_LT(((b.w_NB_B_radps - a.w_NB_B_radps) / (2 * h) - m.alpha_NB_B_radps2).norm(), 1e-2)
        << t;
  }
}

TEST(TruthIntegratorTest, SpeedProfileStepsAreFollowedThroughTheSpeedLag) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.speed_mps = 1;
  c.speed_profile = {{10, 0}, {20, 2}};
  c.vehicle.speed_lag_s = 0.5;
  TruthIntegrator truth(c);
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(10)).speed_mps, 1, 1e-9);
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(10.5)).speed_mps, std::exp(-1), 1e-8);
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(19.9)).speed_mps, 0, 1e-8);
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(20.5)).speed_mps, 2 * (1 - std::exp(-1)), 1e-7);
  // commands are right-continuous: at the step the new command applies (speed still continuous)
  TruthIntegrator again(c);
  const TruthSample at = again.Sample(TimeFromSeconds(20));
  EXPECT_EQ(at.speed_cmd_mps, 2);
}

// ---- path following -----------------------------------------------------------------------

TEST(TruthIntegratorTest, FollowsSeed003RectangleClockwiseWithPurePursuit) {
  TruthConfig c;
  c.origin = {34.2, 108.9, 400};
  c.path = MakeRectangle({-7, -7}, 15, 15, 0, true, 1);
  c.speed_mps = 0.5;
  c.guidance.lookahead_m = 2;
  TruthIntegrator truth(c);
  double max_straight = 0, max_corner = 0;
  for (int k = 0; k <= 1300; ++k) {
    const TruthSample s = truth.Sample(TimeFromSeconds(0.1 * k));
    const Eigen::Vector2d p = s.p_NB_N_m.head<2>();
    // distance to the nearest corner
    double dc = 1e9;
    for (const auto& v : c.path->vertices()) dc = std::min(dc, (p - v.p_N_m).norm());
    // mid-side (the transient after a corner has decayed) or near a corner
    double& m = dc > 7 ? max_straight : max_corner;
    m = std::max(m, std::abs(s.cross_track_m));
    EXPECT_LE(std::abs(s.steer_rad), 32 * kDeg + 1e-12);
  }
  // clockwise: first north, then east
  EXPECT_GT(truth.Sample(TimeFromSeconds(130)).p_NB_N_m.x(), -7.5);
  EXPECT_EQ(truth.root_events(), 4);  // three corners and the end
  EXPECT_LT(max_straight, 0.05);
  EXPECT_GT(max_corner, 0.1);  // pure pursuit cuts the corners with a 2 m look-ahead
  EXPECT_LT(max_corner, 1.0);
  // at the end it stops
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(150)).speed_mps, 0, 1e-6);
  EXPECT_LT(
      (truth.Sample(TimeFromSeconds(150)).p_NB_N_m.head<2>() - Eigen::Vector2d(-7, -7)).norm(),
      0.5);
}

TEST(TruthIntegratorTest, StopsAtAWaypointForItsStopTimeThenContinues) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.path = Path({{{0, 0}, {}, 0}, {{0, 10}, {}, 4.0}, {{0, 20}, {}, 0}});
  c.speed_mps = 1;
  TruthIntegrator truth(c);
  double t_stop = -1, t_restart = -1, y_stopped = 0, prev_speed = 1;
  for (int k = 0; k <= 4000; ++k) {
    const double t = 0.01 * k;
    const TruthSample s = truth.Sample(TimeFromSeconds(t));
    if (t_stop < 0 && s.speed_cmd_mps == 0) t_stop = t;
    if (t_stop > 0 && t_restart < 0 && s.speed_cmd_mps > 0) {
      t_restart = t;
      y_stopped = s.p_NB_N_m.y();
      EXPECT_LT(prev_speed, 1e-3);  // standing still just before the restart
    }
    prev_speed = s.speed_mps;
  }
  ASSERT_GT(t_stop, 0);
  EXPECT_NEAR(t_restart - t_stop, 4.0, 0.011);
  EXPECT_NEAR(y_stopped, 10, 0.05);
  EXPECT_NEAR(truth.Sample(TimeFromSeconds(40)).p_NB_N_m.y(), 20, 0.3);
  EXPECT_EQ(truth.root_events(), 2);
}

TEST(TruthIntegratorTest, DiffDriveTurnsInPlaceAtASharpCorner) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.vehicle = VehicleParams::DiffDrive();
  c.path = Path({{{0, 0}, {}, 0}, {{0, 5}, {}, 0}, {{5, 5}, {}, 0}});
  c.speed_mps = 0.5;
  TruthIntegrator truth(c);
  bool turned_in_place = false;
  for (int k = 0; k <= 400; ++k) {
    const TruthSample s = truth.Sample(TimeFromSeconds(0.1 * k));
    if (std::abs(s.speed_mps) < 1e-3 && std::abs(s.w_NB_B_radps.z()) > 0.3) {
      turned_in_place = true;
      // wheels turn in opposite directions, right-hand turn: left wheel forward
      EXPECT_GT(s.wheel_speed_left_mps, 0);
      EXPECT_LT(s.wheel_speed_right_mps, 0);
      EXPECT_LT((s.p_NB_N_m.head<2>() - Eigen::Vector2d(0, 5)).norm(), 0.1);
    }
  }
  EXPECT_TRUE(turned_in_place);
  const TruthSample end = truth.Sample(TimeFromSeconds(40));
  EXPECT_NEAR(end.p_NB_N_m.x(), 5, 0.3);
  EXPECT_NEAR(end.p_NB_N_m.y(), 5, 0.05);
}

TEST(TruthIntegratorTest, TractorFollowsBoustrophedonRowsAndHeadlandTurns) {
  TruthConfig c = testing::TractorFieldConfig();
  BoustrophedonSpec b;
  b.row_length_m = 40;
  b.row_spacing_m = 7.5;
  b.rows = 3;
  b.turn_radius_m = 3.5;
  c.path = MakeBoustrophedon(b);
  TruthIntegrator truth(c);
  double max_row = 0, max_any = 0;
  const double t_end = (c.path->length_m() + 5) / c.speed_mps;
  for (double t = 0; t <= t_end; t += 0.2) {
    const TruthSample s = truth.Sample(TimeFromSeconds(t));
    max_any = std::max(max_any, std::abs(s.cross_track_m));
    if (s.p_NB_N_m.y() > 10 && s.p_NB_N_m.y() < 30)
      max_row = std::max(max_row, std::abs(s.cross_track_m));
  }
  EXPECT_LT(max_row, 0.02);
  EXPECT_LT(max_any, 0.5);
  const TruthSample end = truth.Sample(TimeFromSeconds(t_end));
  EXPECT_NEAR(end.p_NB_N_m.x(), 15, 0.3);  // third row, first turn to the right (east)
  EXPECT_NEAR(end.speed_mps, 0, 0.05);
}

}  // namespace
}  // namespace hil::truth

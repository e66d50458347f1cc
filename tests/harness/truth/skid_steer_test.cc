// The skid-steer model (vehicle.h): the ICR kinematics of Martínez et al. 2005 / Mandow et al.
// 2007 in the truth. The expected values are derived here from the model's definition: the tracks'
// ICRs at y = ±χ·track/2, the body's ICR x_v ahead of the reference point.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "hil/truth/truth_integrator.h"
#include "hil/truth/vehicle.h"

namespace hil::truth {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

VehicleParams Skid(double chi, double x_v) {
  VehicleParams p = VehicleParams::SkidSteer();
  p.track_m = 0.5;
  p.icr_expansion = chi;
  p.icr_offset_m = x_v;
  return p;
}

TEST(SkidSteerTest, TheTracksIcrsLieChiTimesHalfTheTrackOutAndXvAhead) {
  const VehicleParams p = Skid(1.6, 0.07);
  const double v_l = 0.3, v_r = 0.7;  // track ground speeds
  const PlanarBodyVelocity b = BodyVelocityOf(p, v_l, v_r);
  // a track's ICR is where its contact line's ground velocity vanishes: y_i = (v_x − v_i)/ω,
  // x = −v_y/ω (body frame, x forward, y left)
  EXPECT_NEAR((b.forward_mps - v_l) / b.yaw_rate_radps, 1.6 * 0.5 / 2, 1e-12);
  EXPECT_NEAR((b.forward_mps - v_r) / b.yaw_rate_radps, -1.6 * 0.5 / 2, 1e-12);
  EXPECT_NEAR(-b.lateral_mps / b.yaw_rate_radps, 0.07, 1e-12);
  // Mandow et al.'s forward speed (v_r·y_l − v_l·y_r)/(y_l − y_r), symmetric ICRs
  EXPECT_NEAR(b.forward_mps, (v_r * 0.4 - v_l * -0.4) / 0.8, 1e-12);
  // and back: the wheel speeds of that motion are the ones given
  const WheelGroundSpeeds w = WheelSpeedsOf(p, b.forward_mps, b.yaw_rate_radps);
  EXPECT_NEAR(w.left_mps, v_l, 1e-12);
  EXPECT_NEAR(w.right_mps, v_r, 1e-12);
}

TEST(SkidSteerTest, TurningRadiusIsChiTimesTheDiffDriveRadiusOfTheTrackSpeeds) {
  const double v_l = 0.4, v_r = 0.6, track = 0.5;
  const double r_commanded = track / 2 * (v_r + v_l) / (v_r - v_l);  // 1.25 m as a diff drive
  for (const double chi : {1.0, 1.5, 2.5}) {
    const PlanarBodyVelocity b = BodyVelocityOf(Skid(chi, 0), v_l, v_r);
    EXPECT_NEAR(b.forward_mps / b.yaw_rate_radps, chi * r_commanded, 1e-12) << chi;
  }
  // χ = 1 and x_v = 0: exactly the differential drive
  VehicleParams dd = VehicleParams::DiffDrive();
  dd.track_m = track;
  const PlanarBodyVelocity a = BodyVelocityOf(Skid(1.0, 0), v_l, v_r),
                           d = BodyVelocityOf(dd, v_l, v_r);
  EXPECT_EQ(a.yaw_rate_radps, d.yaw_rate_radps);
  EXPECT_EQ(a.forward_mps, d.forward_mps);
  EXPECT_EQ(d.lateral_mps, 0.0);
}

// Open loop at constant speed and yaw rate: the reference point runs on a circle about the body's
// ICR (x_v, v/ω), of radius √(v² + (x_v·ω)²)/ω, its velocity turned atan(−x_v·ω/v) from the body
// x axis (sideslip to the outside of the turn for x_v > 0), and the wheels' ground speeds are
// v ∓ ω·χ·track/2.
TEST(SkidSteerTest, ConstantCommandsDriveACircleAboutTheBodysIcrWithSideslip) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.vehicle = Skid(1.5, 0.1);
  c.speed_mps = 0.5;
  c.yaw_rate_dps = 20;
  c.start_p_N_m = Eigen::Vector2d(0, 0);
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const double w = 20 * kDeg, v = 0.5, v_y = -0.1 * w;
  const double radius = std::hypot(v, v_y) / w;
  // steady state after the lags (τ 0.3 s, 0.2 s): a full turn takes 18 s; sample one turn late
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  constexpr int kN = 360;
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < kN; ++k) {
    const TruthSample s = truth.Sample(TimeFromSeconds(20 + 18.0 * k / kN));
    points.push_back(s.p_NB_N_m.head<2>());
    centre += points.back() / kN;
    if (k % 90 != 0) continue;
    const Eigen::Vector3d v_B = s.q_NB.conjugate() * s.v_NB_N_mps;
    EXPECT_NEAR(v_B.x(), v, 1e-6);
    EXPECT_NEAR(v_B.y(), v_y, 1e-6);
    EXPECT_NEAR(std::atan2(v_B.y(), v_B.x()), std::atan2(v_y, v), 1e-6);
    EXPECT_NEAR(s.w_NB_B_radps.z(), w, 1e-9);
    EXPECT_NEAR(s.wheel_speed_left_mps, v - w * 1.5 * 0.5 / 2, 1e-6);
    EXPECT_NEAR(s.wheel_speed_right_mps, v + w * 1.5 * 0.5 / 2, 1e-6);
    // the acceleration is centripetal: |a| = |v|²/radius
    EXPECT_NEAR(s.a_NB_N_mps2.norm(), (v * v + v_y * v_y) / radius, 1e-6);
  }
  for (const Eigen::Vector2d& p : points) EXPECT_NEAR((p - centre).norm(), radius, 1e-5);
  // the centre of the circle is the body's ICR: (x_v, v/ω) in the body frame
  const TruthSample s = truth.Sample(TimeFromSeconds(30));
  const Eigen::Vector3d icr_N = s.p_NB_N_m + s.q_NB * Eigen::Vector3d(0.1, v / w, 0);
  EXPECT_NEAR((icr_N.head<2>() - centre).norm(), 0, 1e-5);
}

TEST(SkidSteerTest, TurnsInPlaceAboutThePointXvAheadOfTheAxle) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.vehicle = Skid(1.5, 0.1);
  c.speed_mps = 0;
  c.yaw_rate_dps = 30;
  c.start_p_N_m = Eigen::Vector2d(3, 4);
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  // the reference point circles the ICR 0.1 m ahead of it (radius x_v); the ICR stays put
  Eigen::Vector3d first_icr;
  for (int k = 0; k < 4; ++k) {
    const TruthSample s = truth.Sample(TimeFromSeconds(5 + 3 * k));
    const Eigen::Vector3d icr = s.p_NB_N_m + s.q_NB * Eigen::Vector3d(0.1, 0, 0);
    if (k == 0) first_icr = icr;
    EXPECT_NEAR((icr - first_icr).head<2>().norm(), 0, 1e-6);
    EXPECT_NEAR(s.wheel_speed_right_mps, 30 * kDeg * 1.5 * 0.5 / 2, 1e-9);
  }
}

}  // namespace
}  // namespace hil::truth

#include "hil/truth/truth_integrator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hil::truth {
namespace {

TEST(TruthIntegratorTest, StraightLineAtConstantSpeedHasZeroBodyRate) {
  TruthConfig c;
  c.origin = {35.4796096, 50.5979765, 1300};
  c.heading_deg = 90;  // east
  c.speed_mps = 1.6 / 3.6;
  c.earth_rotation = false;
  TruthIntegrator truth(c);
  const TruthSample s = truth.Sample(TimeFromSeconds(100));
  EXPECT_NEAR(s.p_NB_N_m.x(), 100 * c.speed_mps, 1e-6);
  EXPECT_NEAR(s.p_NB_N_m.y(), 0, 1e-6);
  EXPECT_NEAR(s.w_IB_B_radps.norm(), 0, 1e-12);
  // level and unaccelerated: the accelerometer reads +g up
  EXPECT_NEAR(s.f_B_mps2.head<2>().norm(), 0, 1e-9);
  EXPECT_NEAR(s.f_B_mps2.z(), -s.gravity_N_mps2.z(), 1e-9);
}

TEST(TruthIntegratorTest, ConstantSteeringGivesCircleOfRadiusLOverTanDelta) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.heading_deg = 0;
  c.speed_mps = 1.0;
  c.steer_deg = 20;
  c.wheelbase_m = 0.84;
  TruthIntegrator truth(c);
  const double R = c.wheelbase_m / std::tan(20 * M_PI / 180);
  // centre of the circle: to the left (west) of a northbound start
  const Eigen::Vector2d centre(-R, 0);
  for (double t = 1; t < 30; t += 3.7) {
    const TruthSample s = truth.Sample(TimeFromSeconds(t));
    EXPECT_NEAR((s.p_NB_N_m.head<2>() - centre).norm(), R, 1e-6) << "t=" << t;
    // centripetal specific force v²/R to the left (body +y)
    EXPECT_NEAR(s.f_B_mps2.y(), 1.0 / R, 1e-6);
  }
}

TEST(TruthIntegratorTest, EarlierRequestRestartsDeterministically) {
  TruthConfig c;
  c.origin = {35, 50, 0};
  c.steer_deg = 5;
  TruthIntegrator truth(c);
  const TruthSample a = truth.Sample(TimeFromSeconds(10));
  truth.Sample(TimeFromSeconds(50));
  const TruthSample b = truth.Sample(TimeFromSeconds(10));
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
}

}  // namespace
}  // namespace hil::truth

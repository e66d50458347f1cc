// Navigator behaviours that do not need the simulator: the seed-000 three-receiver mode, late and
// out-of-order inputs, bad input.
#include "hil/estimator/navigator.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hil::estimator {
namespace {

constexpr GpsNs kT0 = 1'400'000'000LL * 1'000'000'000LL;

TEST(NavigatorTest, ThreeReceiversGiveCentreAndHeading) {
  // GIVEN seed 000's three antennas on a 3 m circle, 120° apart
  NavigatorParams p;
  p.mode = NavMode::kMultiGnss;
  for (int i = 0; i < 3; ++i) {
    const double a = i * 2 * M_PI / 3;
    p.multi_antenna_B_m.col(i) = Eigen::Vector3d(3 * std::cos(a), 3 * std::sin(a), 0);
  }
  Navigator nav(p);
  const LocalTangentFrame frame({35.4796096, 50.5979765, 1300});
  const Eigen::Vector3d centre(12.0, -7.0, 0.0);
  const double yaw = 0.4;  // counter-clockwise from east
  // WHEN the three fixes of one epoch arrive (in any order)
  for (int i : {2, 0, 1}) {
    GnssSample g;
    g.t = kT0;
    g.antenna = i;
    g.position = frame.ToLla(centre + Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * p.multi_antenna_B_m.col(i));
    g.pos_std_enu_m.setConstant(0.3);
    nav.Push(g);
  }
  // THEN the solution is the circle's centre with the body heading
  const NavOutput o = nav.Output();
  ASSERT_TRUE(o.valid);
  const Eigen::Vector3d c = frame.ToLocal(o.position);
  EXPECT_LT((c - centre).head<2>().norm(), 1e-6);
  const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(x.y(), x.x()), yaw, 1e-5);  // (the navigator anchors its own tangent plane at the first fix)
}

TEST(NavigatorTest, CountsOutOfOrderImuAndRejectsBadInput) {
  Navigator nav(NavigatorParams{});
  ImuSample s;
  s.t = kT0;
  s.dt_s = 0.01;
  nav.Push(s);
  nav.Push(s);  // same time again
  s.dt_s = std::nan("");
  s.t += 10'000'000;
  nav.Push(s);
  GnssSample g;
  g.position.lat_deg = 123.0;  // impossible latitude
  nav.Push(g);
  EXPECT_EQ(nav.stats().imu_samples, 1u);
  EXPECT_EQ(nav.stats().imu_out_of_order, 1u);
  EXPECT_EQ(nav.stats().bad_input, 2u);
  EXPECT_TRUE(nav.status() & kStatusBadInput);
  EXPECT_FALSE(nav.aligned());
}

}  // namespace
}  // namespace hil::estimator

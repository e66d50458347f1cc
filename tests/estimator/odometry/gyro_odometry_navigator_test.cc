// navd's gyro + wheel-odometry EKF (paper 001): a differential-drive base simulated in closed form
// (constant speed and yaw rate per phase), an IMU whose gyro has a constant bias about its up axis
// (the IMU mounted upside down: z down, so "up" must come from the alignment), and encoders
// quantised to whole counts. The filter must find the bias from the odometry and keep the pose.
#include "hil/estimator/odometry/gyro_odometry_navigator.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace hil::estimator::odometry {
namespace {

constexpr double kImuDt_s = 0.02, kOdoDt_s = 0.1;
constexpr double kRadius_m = 0.1, kTrack_m = 0.5;
constexpr int kCounts = 1200;

struct Truth {
  double t_s = 0, x = 0, y = 0, yaw = 0, left_m = 0, right_m = 0;
};

class Sim {
 public:
  Sim(double bias_radps, double left_slip, double right_slip)
      : bias_(bias_radps), slip_l_(left_slip), slip_r_(right_slip) {}
  // Advances by one IMU step at speed v and yaw rate w (of the ground track).
  ImuSample Step(double v, double w) {
    const double dt = kImuDt_s;
    const double mid = truth_.yaw + 0.5 * w * dt;
    truth_.x += v * dt * std::cos(mid);
    truth_.y += v * dt * std::sin(mid);
    truth_.yaw += w * dt;
    // the wheels' shafts turn for the ground speeds plus what slips
    truth_.left_m += (v - 0.5 * w * kTrack_m) * dt / (1 - slip_l_);
    truth_.right_m += (v + 0.5 * w * kTrack_m) * dt / (1 - slip_r_);
    truth_.t_s += dt;
    ImuSample s;
    s.t = GpsTimeFromNs(std::llround(truth_.t_s * 1e9));
    s.dt_s = dt;
    // IMU z axis down: a counter-clockwise turn reads negative about z; at rest f = (0, 0, -g)
    s.delta_angle_B_rad = Eigen::Vector3d(0, 0, -(w + bias_) * dt);
    s.delta_velocity_B_mps = Eigen::Vector3d(0, 0, -9.81 * dt);
    return s;
  }
  EncoderSample Encoders() const {
    const double per = 2 * std::numbers::pi * kRadius_m / kCounts;
    return {GpsTimeFromNs(std::llround(truth_.t_s * 1e9)),
            static_cast<std::int32_t>(std::floor(truth_.left_m / per)),
            static_cast<std::int32_t>(std::floor(truth_.right_m / per))};
  }
  const Truth& truth() const { return truth_; }
  void set_bias(double b) { bias_ = b; }

 private:
  double bias_, slip_l_, slip_r_;
  Truth truth_;
};

WheelOdometryConfig Config() {
  WheelOdometryConfig c;
  c.wheel_radius_m = kRadius_m;
  c.track_m = kTrack_m;
  c.counts_per_rev = kCounts;
  c.align_s = 2.0;
  c.initial_yaw_rad = 0;
  return c;
}

// Drives for `seconds` at (v, w), the encoders every 0.1 s (one IMU step late, as navd gets them).
void Drive(Sim& sim, GyroOdometryNavigator& nav, double seconds, double v, double w) {
  const int steps = static_cast<int>(std::lround(seconds / kImuDt_s));
  const int per_odo = static_cast<int>(std::lround(kOdoDt_s / kImuDt_s));
  for (int i = 1; i <= steps; ++i) {
    nav.OnImu(sim.Step(v, w));
    if (i % per_odo == 0) {
      const EncoderSample e = sim.Encoders();
      nav.OnImu(sim.Step(v, w));
      nav.OnEncoders(e);
      ++i;
    }
  }
}

TEST(GyroOdometryNavigator, AlignsOnTheUpAxisAndTakesTheStaticBias) {
  Sim sim(0.01, 0, 0);
  GyroOdometryNavigator nav(Config());
  Drive(sim, nav, 1.9, 0, 0);
  EXPECT_FALSE(nav.aligned());
  Drive(sim, nav, 0.2, 0, 0);
  ASSERT_TRUE(nav.aligned());
  // about "up" (−z here) the gyro reads w + bias with w = 0: the bias seen from up is +0.01
  EXPECT_NEAR(nav.filter().bias_radps(), 0.01, 1e-9);
}

TEST(GyroOdometryNavigator, OdometryFindsABiasThatAppearsAfterTheAlignment) {
  // aligned with no bias, then the bias steps to 0.005 rad/s (a drift the alignment did not see):
  // only the wheels can tell; without the feedback the heading would drift 0.3 rad in 60 s
  Sim sim(0.0, 0, 0);
  WheelOdometryConfig c = Config();
  c.filter.odo_yaw_std_rad = 0.001;  // about one count of 0.52 mm over the 0.5 m track
  GyroOdometryNavigator nav(c);
  Drive(sim, nav, 2.1, 0, 0);
  ASSERT_TRUE(nav.aligned());
  EXPECT_NEAR(nav.filter().bias_radps(), 0.0, 1e-12);
  sim.set_bias(0.005);
  Drive(sim, nav, 60, 0.4, 0);
  EXPECT_NEAR(nav.filter().bias_radps(), 0.005, 0.001);
  const std::optional<PlanarSolution> s =
      nav.Output(GpsTimeFromNs(std::llround(sim.truth().t_s * 1e9)));
  ASSERT_TRUE(s);
  EXPECT_LT(std::abs(s->yaw_rad - sim.truth().yaw), 0.02);  // 1.1°, not 17°
  EXPECT_EQ(nav.filter().stats().odometry_rejected, 0u);
}

TEST(GyroOdometryNavigator, FollowsARectangleWithQuantisedEncoders) {
  Sim sim(0.002, 0, 0);
  GyroOdometryNavigator nav(Config());
  Drive(sim, nav, 2.1, 0, 0);
  for (int side = 0; side < 4; ++side) {
    Drive(sim, nav, 20, 0.4, 0);                   // 8 m straight
    Drive(sim, nav, 5, 0, std::numbers::pi / 10);  // a quarter turn in place
  }
  const std::optional<PlanarSolution> s =
      nav.Output(GpsTimeFromNs(std::llround(sim.truth().t_s * 1e9)));
  ASSERT_TRUE(s);
  const double dyaw = std::remainder(s->yaw_rad - sim.truth().yaw, 2 * std::numbers::pi);
  EXPECT_LT(std::abs(dyaw), 0.2 * std::numbers::pi / 180);  // 0.2°
  EXPECT_LT((s->p_EN_m - Eigen::Vector2d(sim.truth().x, sim.truth().y)).norm(), 0.05);
  EXPECT_NEAR(s->bias_radps, 0.002, 2e-4);
  EXPECT_GT(nav.filter().stats().odometry_updates, 900u);
  // only the interval across the alignment's end (its start precedes the heading history)
  EXPECT_LE(nav.stats().outside_history, 1u);
}

TEST(GyroOdometryNavigator, DifferentialSlipBiasesTheOdometryYaw) {
  // the right wheel slips 1 % more: the odometry's yaw rate reads 0.01 v / track too high while
  // the gyro is right; with the bias fed back the filter takes part of it as gyro bias
  Sim sim(0.0, 0.0, 0.01);
  GyroOdometryNavigator nav(Config());
  Drive(sim, nav, 2.1, 0, 0);
  Drive(sim, nav, 30, 0.4, 0);
  const double odo_rate_error = 0.4 / (1 - 0.01) * 0.01 / kTrack_m;  // 8.1 mrad/s
  EXPECT_LT(nav.filter().bias_radps(), -0.1 * odo_rate_error);       // the gyro seems to read low
  EXPECT_GT(nav.filter().bias_radps(), -1.1 * odo_rate_error);
}

TEST(GyroOdometryNavigator, WrappingCountersAndOutOfOrderSamples) {
  GyroOdometryNavigator nav(Config());
  Sim sim(0, 0, 0);
  Drive(sim, nav, 2.1, 0, 0);
  const GpsTime t0 = GpsTimeFromNs(std::llround(sim.truth().t_s * 1e9));
  nav.OnEncoders({t0, INT32_MAX - 5, INT32_MAX - 5});
  const std::optional<PlanarSolution> s0 = nav.Output(t0);
  ASSERT_TRUE(s0);
  nav.OnImu(sim.Step(0, 0));
  nav.OnImu(sim.Step(0, 0));
  nav.OnEncoders({t0 + Nanoseconds(40'000'000), INT32_MIN + 4, INT32_MIN + 4});  // +10 counts
  const std::optional<PlanarSolution> s = nav.Output(t0 + Nanoseconds(40'000'000));
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->p_EN_m.x() - s0->p_EN_m.x(), 10 * 2 * std::numbers::pi * kRadius_m / kCounts,
              1e-6);
  nav.OnEncoders({t0, 0, 0});  // older than the last: dropped
  EXPECT_EQ(nav.stats().out_of_order, 1u);
}

}  // namespace
}  // namespace hil::estimator::odometry

// The navigator with an IMU that cannot be used (aid_sources/imu_usability_control.cc): paper
// 000's robot (0.44 m/s on a line, NEO-5M-like fixes at 1 Hz, a 10 Hz-class IMU model) whose
// accelerometer and gyro carry an engine order aliased near DC, metres per second squared and
// degrees per second wandering with a 250 s period (field_realism/two_stroke_robot). The check
// finds the IMU unusable, the solution is the GNSS + vehicle-model filter, no worse than the
// fixes, and flagged; with a consistent IMU the check never fires and the output is the EKF's,
// bit for bit.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "hil/estimator/navigator.h"

namespace hil::estimator {
namespace {

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Lla kOrigin{35.48, 50.60, 1312.0};
const Eigen::Vector3d kLever(0.84, 0.0, 0.5);
constexpr double kSpeed = 0.44, kYaw = 0.5;

NavigatorParams RobotParams(bool check) {
  NavigatorParams p;
  EkfParams& e = p.ekf;
  e.accel_noise_mps2_rthz = 0.0125;
  e.gyro_noise_radps_rthz = 0.0022;
  e.accel_bias_rw_mps3_rthz = 5e-4;
  e.gyro_bias_rw_radps2_rthz = 1e-4;
  e.init_accel_bias_std_mps2 = 0.8;
  e.init_gyro_bias_std_radps = 0.05;
  e.gnss_error_tau_s = 4.5;
  e.gnss_error_std_m = 0.225;
  e.gnss_error_vertical_std_m = 1.0;
  e.nhc_std_mps = 0.05;
  e.speed_rw_mps_rthz = 5e-4;
  e.speed_dev_std_mps = 0.02;
  e.lever_arm_B_m = kLever;
  p.imu_usability.enabled = check;
  return p;
}

struct Figures {
  double rmse_m = 0, fix_rmse_m = 0, nees = 0;
  int unusable_outputs = 0, outputs = 0;
  bool last_unusable = false;  // the last output's kStatusImuUnusable
  NavigatorStats stats;
};

// `wander` scales the aliased engine (0: a consistent IMU); from `still_from_s` on its offset
// holds still (the engine stopped at a constant phase: a bias again).
Figures RunRobot(bool check, double wander, double duration_s, double still_from_s = 1e9) {
  Navigator nav(RobotParams(check));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(kYaw, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d dir(std::cos(kYaw), std::sin(kYaw), 0);
  nav.InitializeAt(kT0, kOrigin, kSpeed * dir, q);
  const LocalTangentFrame frame(kOrigin);
  const Eigen::Vector3d g_N(0, 0, -NormalGravity(kOrigin.lat_deg, kOrigin.height_m));
  std::mt19937 rng(11);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double dt = 0.01, a_gm = std::exp(-1.0 / 4.5);
  Eigen::Vector2d e(0.225 * n01(rng), 0.225 * n01(rng));
  const Eigen::Vector3d f_B = q.conjugate() * (-g_N);
  const Eigen::Vector3d w_B = q.conjugate() * frame.w_IE_N();
  Figures r;
  double se = 0, se_fix = 0;
  for (long k = 1; static_cast<double>(k) * dt <= duration_s + 1e-9; ++k) {
    const double t = static_cast<double>(k) * dt;
    const double s = wander * std::sin(2 * M_PI * std::min(t, still_from_s) / 250);
    ImuSample imu;
    imu.t = kT0 + Nanoseconds{std::llround(t * 1e9)};
    imu.dt_s = dt;
    const Eigen::Vector3d accel_alias(1.15 * s, 0.77 * s, 2.3 * s);
    const Eigen::Vector3d gyro_alias(0.037 * s, 0.037 * s, 0.020 * s);
    for (int i = 0; i < 3; ++i) {
      imu.delta_velocity_B_mps[i] =
          (f_B[i] + accel_alias[i]) * dt + 0.0125 * std::sqrt(dt) * n01(rng);
      imu.delta_angle_B_rad[i] = (w_B[i] + gyro_alias[i]) * dt + 0.0022 * std::sqrt(dt) * n01(rng);
    }
    nav.Push(imu);
    if (k % 100 == 0) {
      e = a_gm * e + 0.225 * std::sqrt(1 - a_gm * a_gm) * Eigen::Vector2d(n01(rng), n01(rng));
      const Eigen::Vector3d p_ant =
          kSpeed * t * dir + q * kLever +
          Eigen::Vector3d(e.x() + 0.04 * n01(rng), e.y() + 0.04 * n01(rng), 0.1 * n01(rng));
      GnssSample g;
      g.t = imu.t;
      g.position = frame.ToLla(p_ant);
      g.pos_std_enu_m = Eigen::Vector3d(0.04, 0.04, 0.1);
      g.has_velocity = true;
      g.vel_enu_mps = kSpeed * dir + Eigen::Vector3d(0.1 * n01(rng), 0.1 * n01(rng), 0);
      g.vel_std_enu_mps = Eigen::Vector3d(0.1, 0.1, 0.2);
      g.hdop = 1.0;
      g.fix_quality = 1;
      nav.Push(g);
      if (t >= 120) se_fix += (p_ant - q * kLever - kSpeed * t * dir).head<2>().squaredNorm();
    }
    nav.Update();
    if (k % 100 == 50 && t >= 120) {
      const NavOutput o = nav.Output();
      const double to = static_cast<double>((o.t - kT0).count()) * 1e-9;
      const Eigen::Vector2d err = (o.p_N_m - kSpeed * to * dir).head<2>();
      se += err.squaredNorm();
      r.nees += err.x() * err.x() / (o.pos_std_enu_m.x() * o.pos_std_enu_m.x()) +
                err.y() * err.y() / (o.pos_std_enu_m.y() * o.pos_std_enu_m.y());
      r.last_unusable = (o.status & kStatusImuUnusable) != 0;
      r.unusable_outputs += r.last_unusable;
      ++r.outputs;
    }
  }
  r.rmse_m = std::sqrt(se / r.outputs);
  r.fix_rmse_m = std::sqrt(se_fix / r.outputs);
  r.nees /= r.outputs;
  r.stats = nav.stats();
  return r;
}

TEST(ImuUsabilityControlTest, ImuFarOutsideItsModelFallsBackToTheVehicleModel) {
  const Figures off = RunRobot(false, 1.0, 600);
  const Figures on = RunRobot(true, 1.0, 600);
  std::printf(
      "wandering IMU: EKF alone %.3f m, with the check %.3f m (NEES h %.2f), fixes %.3f m; "
      "%d of %d outputs from the vehicle model, statistic %.1f (threshold %.1f)\n",
      off.rmse_m, on.rmse_m, on.nees, on.fix_rmse_m, on.unusable_outputs, on.outputs,
      on.stats.imu_consistency_stat, on.stats.imu_consistency_threshold);
  EXPECT_GE(on.stats.imu_unusable_periods, 1u);
  EXPECT_TRUE(on.stats.imu_unusable);
  // still far from consistent: above the return threshold (χ²(11)'s 95 % quantile, 19.68)
  EXPECT_GT(on.stats.imu_consistency_stat, 19.68);
  EXPECT_GT(on.unusable_outputs, on.outputs * 3 / 4);
  // no worse than the fixes (two_stroke_robot's criterion), and an honest σ (2 dof)
  EXPECT_LT(on.rmse_m, on.fix_rmse_m);
  EXPECT_LT(on.rmse_m, off.rmse_m);
  EXPECT_LT(on.nees, 6.0);
}

TEST(ImuUsabilityControlTest, BackToTheInsWhenTheImuIsConsistentAgain) {
  // the offset wanders for 300 s, then holds (a bias): the INS's solution again by the end
  const Figures r = RunRobot(true, 1.0, 900, 300);
  std::printf(
      "wander until 300 s: %d of %d outputs from the vehicle model, %.3f m (fixes %.3f m)\n",
      r.unusable_outputs, r.outputs, r.rmse_m, r.fix_rmse_m);
  EXPECT_EQ(r.stats.imu_unusable_periods, 1u);
  EXPECT_FALSE(r.stats.imu_unusable);
  EXPECT_FALSE(r.last_unusable);
  EXPECT_GT(r.unusable_outputs, 100);
  EXPECT_LT(r.unusable_outputs, r.outputs - 300);
  // the returning EKF re-converges its bias from where the wander left it, which its rounding
  // decides: over the whole run 0.245 m on x86-64 and 0.340 m on arm64 (FMA contraction) against
  // the fixes' 0.32; a gross bound on it, not the fixes' own (ours)
  EXPECT_LT(r.rmse_m, 1.25 * r.fix_rmse_m);
}

TEST(ImuUsabilityControlTest, ConsistentImuKeepsTheEkfBitForBit) {
  const Figures off = RunRobot(false, 0.0, 400);
  const Figures on = RunRobot(true, 0.0, 400);
  EXPECT_EQ(on.stats.imu_unusable_periods, 0u);
  EXPECT_GT(on.stats.imu_consistency_tests, 30u);
  EXPECT_LT(on.stats.imu_consistency_stat, on.stats.imu_consistency_threshold);
  EXPECT_EQ(on.unusable_outputs, 0);
  EXPECT_EQ(on.rmse_m, off.rmse_m);
  EXPECT_EQ(on.nees, off.nees);
}

}  // namespace
}  // namespace hil::estimator

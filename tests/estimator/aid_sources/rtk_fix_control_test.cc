// The navigator against wrong RTK fixes (aid_sources/rtk_fix_control.cc): a level vehicle on a
// straight line at 1 m/s, an industrial-grade IMU at 100 Hz, RTK fixes at 10 Hz in episodes
// separated by 5 s of float; a wrong episode's fixes are off by a constant offset (a wrong integer
// fix), reported fixed with centimetre σ. The filter must not follow a wrong episode, and when it
// has followed one (the run's first), it must move to the right frame once two episodes agree.
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/navigator.h"

namespace hil::estimator {
namespace {

using namespace std::chrono_literals;

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Lla kOrigin{45.75, 126.63, 150.0};
constexpr double kSpeed = 1.0, kYaw = 0.3;

// An episode: fixed from from_s to to_s, off by offset_N_m; float before it (5 s) and after.
struct Episode {
  double from_s, to_s;
  Eigen::Vector3d offset_N_m;
};

NavigatorParams Params() {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.fusion_horizon = 0ns;
  p.ekf.accel_noise_mps2_rthz = 0.003;
  p.ekf.gyro_noise_radps_rthz = 7.5e-5;
  p.ekf.init_pos_std_m = 0.3;  // aligned on a float solution
  p.ekf.init_vel_std_mps = 0.05;
  p.ekf.init_roll_pitch_std_rad = 0.01;
  p.ekf.init_yaw_std_rad = 0.02;
  // the tractor rig's GNSS error models (seed004_tractor_rtk.yaml): fixed 8 mm over 30 s, float
  // 0.2 m over 5 s, the fixes' white σ reported apart
  p.ekf.gnss_error_tau_s = 30;
  p.ekf.gnss_error_std_m = 0.008;
  p.ekf.gnss_float_error_tau_s = 5;
  p.ekf.gnss_float_error_std_m = 0.2;
  return p;
}

struct LineRig {
  explicit LineRig(std::vector<Episode> episodes) : nav(Params()), plan(std::move(episodes)) {
    nav.InitializeAt(kT0, kOrigin, Velocity(), Attitude());
  }
  static Eigen::Vector3d Velocity() {
    return {kSpeed * std::cos(kYaw), kSpeed * std::sin(kYaw), 0};
  }
  static Eigen::Quaterniond Attitude() {
    return Eigen::Quaterniond(Eigen::AngleAxisd(kYaw, Eigen::Vector3d::UnitZ()));
  }
  // IMU at 100 Hz, a fix every 0.1 s (its quality and offset from the plan), up to t_end_s
  void Run(double t_end_s) {
    const double dt = 0.01;
    const Eigen::Matrix3d C = Attitude().toRotationMatrix();
    const Eigen::Vector3d w_ie = frame.w_IE_N();
    const Eigen::Vector3d g_N(0, 0, -NormalGravity(kOrigin.lat_deg, kOrigin.height_m));
    const Eigen::Vector3d f_B = C.transpose() * (2.0 * w_ie.cross(Velocity()) - g_N);
    const Eigen::Vector3d w_B = C.transpose() * w_ie;
    for (; t_s < t_end_s - 1e-9; ++k) {
      ImuSample s;
      t_s += dt;
      s.t = kT0 + Nanoseconds{std::llround(t_s * 1e9)};
      s.dt_s = dt;
      for (int i = 0; i < 3; ++i) {
        s.delta_velocity_B_mps[i] = f_B[i] * dt + 0.003 * std::sqrt(dt) * n01(rng);
        s.delta_angle_B_rad[i] = w_B[i] * dt + 7.5e-5 * std::sqrt(dt) * n01(rng);
      }
      if ((k + 1) % 10 == 0) Fix(s.t);
      nav.Push(s);
      nav.Update();
    }
  }
  void Fix(GpsTime t) {
    GnssSample g;
    g.t = t;
    g.fix_quality = 5;
    double std_m = 0.02;  // float: decimetres, wandering over seconds (float_error)
    Eigen::Vector3d error = float_error;
    for (const Episode& e : plan) {
      if (t_s < e.from_s || t_s >= e.to_s) continue;
      g.fix_quality = 4;
      std_m = 0.005;
      error = e.offset_N_m;
    }
    for (int i = 0; i < 3; ++i) {
      float_error[i] = 0.98 * float_error[i] + 0.2 * std::sqrt(1 - 0.98 * 0.98) * n01(rng);
      error[i] += 0.005 * n01(rng);
    }
    g.position = frame.ToLla(Velocity() * t_s + error);
    g.pos_std_enu_m.setConstant(std_m);
    g.has_velocity = true;
    g.vel_enu_mps = Velocity();
    for (int i = 0; i < 3; ++i) g.vel_enu_mps[i] += 0.02 * n01(rng);
    g.vel_std_enu_mps.setConstant(0.02);
    nav.Push(g);
  }
  double HorizontalError() const {
    return (nav.Output().p_N_m - Velocity() * t_s).head<2>().norm();
  }
  // the largest horizontal error from now until t_end_s
  double MaxHorizontalErrorUntil(double t_end_s) {
    double max_m = 0;
    while (t_s < t_end_s - 1e-9) {
      Run(std::min(t_s + 0.1, t_end_s));
      max_m = std::max(max_m, HorizontalError());
    }
    return max_m;
  }

  Navigator nav;
  std::vector<Episode> plan;
  LocalTangentFrame frame{kOrigin};
  std::mt19937 rng{41};
  std::normal_distribution<double> n01{0.0, 1.0};
  Eigen::Vector3d float_error = Eigen::Vector3d::Zero();
  double t_s = 0;
  long k = 0;
};

const Eigen::Vector3d kRight = Eigen::Vector3d::Zero();

TEST(RtkFixControlTest, AFilterThatFollowedAWrongFirstEpisodeMovesWhenTwoOthersAgree) {
  // the run's first fix is wrong: nothing contradicts it, the filter follows it
  const Eigen::Vector3d wrong(0.20, -0.12, 0.15);
  LineRig rig({{2, 30, wrong}, {35, 50, kRight}, {55, 70, kRight}, {75, 90, kRight}});
  rig.Run(30);
  EXPECT_GT(rig.HorizontalError(), 0.15);
  // the second episode is right (one against one: the float solution the filter held before the
  // first decides), the third agrees with it: from then on the filter is in their frame
  rig.Run(56);
  EXPECT_LT(rig.MaxHorizontalErrorUntil(90), 0.05);
  EXPECT_EQ(rig.nav.stats().gnss_resets, 0U);
}

TEST(RtkFixControlTest, AWrongEpisodeTheGateWouldTakeIsHeldOff) {
  // a right filter, then a wrong fix a few σ of the filter off (within its 5σ outlier gate)
  const Eigen::Vector3d wrong(0.07, 0.04, 0.03);
  LineRig rig({{2, 30, kRight}, {35, 60, wrong}, {65, 80, kRight}});
  rig.Run(35);
  EXPECT_LT(rig.MaxHorizontalErrorUntil(80), 0.06);
  EXPECT_EQ(rig.nav.stats().gnss_resets, 0U);
}

TEST(RtkFixControlTest, ARightFilterKeepsItsFrameAgainstWrongEpisodes) {
  LineRig rig({{2, 30, kRight},
               {35, 60, Eigen::Vector3d(0.3, 0.1, -0.2)},
               {65, 80, kRight},
               {85, 110, Eigen::Vector3d(-0.1, 0.25, 0.1)},
               {115, 130, kRight}});
  rig.Run(3);
  EXPECT_LT(rig.MaxHorizontalErrorUntil(130), 0.06);
  EXPECT_EQ(rig.nav.stats().gnss_resets, 0U);
  EXPECT_EQ(rig.nav.stats().rtk_suspect_episodes, 2U);
}

TEST(RtkFixControlTest, ASuspectEpisodeWhoseOffsetChangesIsJudgedAgain) {
  // a wrong fix whose image in the position moves by 0.15 m at 45 s, still reported fixed (the
  // geometry of its wrong integers changed): the fixes less the first offset would pull the
  // filter by that much
  LineRig rig({{2, 30, kRight},
               {35, 45, Eigen::Vector3d(0.3, 0.1, -0.2)},
               {45, 60, Eigen::Vector3d(0.45, 0.1, -0.2)},
               {65, 80, kRight}});
  rig.Run(35);
  EXPECT_LT(rig.MaxHorizontalErrorUntil(80), 0.06);
  EXPECT_EQ(rig.nav.stats().gnss_resets, 0U);
}

TEST(RtkFixControlTest, HealthCountsTheFramesAndTheSwitch) {
  LineRig rig({{2, 30, Eigen::Vector3d(0.20, -0.12, 0.15)}, {35, 50, kRight}, {55, 70, kRight}});
  rig.Run(70);
  const NavigatorStats& s = rig.nav.stats();
  // one against one at 35 s, decided by the float solution (the filter was aligned on the truth,
  // σ 0.3 m): the filter moves to the second episode at once, the third agrees
  EXPECT_EQ(s.rtk_frame_switches, 1U);
  EXPECT_EQ(s.rtk_frame_episodes, 2U);  // the two right episodes
  EXPECT_EQ(s.rtk_other_frames, 1U);    // the first, wrong one, kept as a hypothesis
  EXPECT_EQ(s.rtk_suspect_episodes, 0U);
  EXPECT_LT(rig.HorizontalError(), 0.03);
}

}  // namespace
}  // namespace hil::estimator

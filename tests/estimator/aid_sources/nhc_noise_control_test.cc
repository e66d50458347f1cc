// The non-holonomic constraint against its own innovations (NhcNoiseParams, issue 39: a walker,
// whose sway and crab the constraint's premise does not allow, made navd + NHC worse than navd
// without it). A level vehicle going straight, its IMU and GNSS generated here with a seeded noise;
// the vehicle either keeps to the constraint or crabs and sways (body lateral velocity
// 0.17 m/s + 0.31 m/s at 1 Hz), then loses the GNSS for 10 s.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/navigator.h"

#include "fixtures/imu_sample_from_truth.h"

namespace hil::estimator {
namespace {

using namespace std::chrono_literals;

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Lla kOrigin{48.0, 11.0, 500.0};
constexpr double kPi = 3.14159265358979323846;
// the IMU's biases, unknown to the filter (m/s², rad/s: 0.1 °/s about z)
const Eigen::Vector3d kAccelBias_B(0.03, -0.03, 0.02);
const Eigen::Vector3d kGyroBias_B(0.0, 0.0, 0.1 * kPi / 180.0);
// the IMU: white noise 0.005 m/s/√s and 5e-5 rad/√s, the biases above
const testing::ImuNoise kImu{0.005, 5e-5, kAccelBias_B, kGyroBias_B};

// A level vehicle whose course turns on a circle (yaw rate w_radps) at speed_mps; a walker adds a
// crab, its body's x axis crab(t) = crab_rad + crab_swing_rad sin(2π t / 40 s) right of its course
// (a device carried by hand), a lateral sway of sway_m at step_hz and a vertical bounce of
// bounce_m at twice that.
struct Truth {
  double speed_mps = 1.2, w_radps = 0.05, crab_rad = 0.0, crab_swing_rad = 0.0, sway_m = 0.0;
  double bounce_m = 0.0, step_hz = 1.0, yaw0_rad = 0.3;
  double Course(double t) const { return yaw0_rad + w_radps * t; }
  double CrabW() const { return 2 * kPi / 40.0; }
  double Yaw(double t) const {
    return Course(t) - crab_rad - crab_swing_rad * std::sin(CrabW() * t);
  }
  double YawRate(double t) const {
    return w_radps - crab_swing_rad * CrabW() * std::cos(CrabW() * t);
  }
  double W() const { return 2 * kPi * step_hz; }
  Eigen::Vector3d Position(double t) const {
    const double c0 = Course(0), c = Course(t), r = speed_mps / w_radps;
    const Eigen::Vector3d left(-std::sin(c), std::cos(c), 0);
    return Eigen::Vector3d(r * (std::sin(c) - std::sin(c0)), -r * (std::cos(c) - std::cos(c0)),
                           bounce_m * std::sin(2 * W() * t)) +
           left * sway_m * std::sin(W() * t);
  }
  Eigen::Vector3d Velocity(double t) const {
    const double h = 1e-4;
    return (Position(t + h) - Position(t - h)) / (2 * h);
  }
  Eigen::Vector3d Acceleration(double t) const {
    const double h = 1e-3;
    return (Position(t + h) - 2 * Position(t) + Position(t - h)) / (h * h);
  }
  Eigen::Quaterniond Attitude(double t) const {
    return Eigen::Quaterniond(Eigen::AngleAxisd(Yaw(t), Eigen::Vector3d::UnitZ()));
  }
};

NavigatorParams Params(bool check) {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.fusion_horizon = 0ns;
  p.ekf.accel_noise_mps2_rthz = 0.005;
  p.ekf.gyro_noise_radps_rthz = 5e-5;
  p.ekf.init_pos_std_m = 0.05;
  p.ekf.init_vel_std_mps = 0.05;
  p.ekf.init_roll_pitch_std_rad = 0.01;
  p.ekf.init_yaw_std_rad = 0.02;
  p.ekf.nhc_std_mps = 0.1;  // walk_0827's --nhc-std-mps
  p.nhc_noise.enabled = check;
  return p;
}

// IMU at 100 Hz and 4 Hz fixes (none in [gap_from_s, gap_to_s)); the horizontal error at the end.
struct DriveResult {
  NavigatorStats stats;
  double end_error_m = 0;
};
DriveResult Drive(const Truth& truth, bool check, double gap_from_s, double gap_to_s) {
  Navigator nav(Params(check));
  nav.InitializeAt(kT0, kOrigin, truth.Velocity(0), truth.Attitude(0));
  const LocalTangentFrame frame{kOrigin};
  const Eigen::Vector3d g_N(0, 0, -NormalGravity(kOrigin.lat_deg, kOrigin.height_m));
  const Eigen::Vector3d w_ie = frame.w_IE_N();
  std::mt19937 rng{39};
  std::normal_distribution<double> n01{0.0, 1.0};
  const double dt = 0.01;
  double t_s = 0;
  for (long k = 0; t_s < gap_to_s - 1e-9; ++k) {
    const double tm = t_s + 0.5 * dt;
    const Eigen::Matrix3d C = truth.Attitude(tm).toRotationMatrix();
    const Eigen::Vector3d w_B = Eigen::Vector3d(0, 0, truth.YawRate(tm)) + C.transpose() * w_ie;
    const Eigen::Vector3d f_N = truth.Acceleration(tm) + 2.0 * w_ie.cross(truth.Velocity(tm)) - g_N;
    t_s += dt;
    const ImuSample s = testing::ImuSampleFromTruth(kT0 + Nanoseconds{std::llround(t_s * 1e9)}, dt,
                                                    C, f_N, w_B, kImu, rng, n01);
    if ((k + 1) % 25 == 0 && (t_s < gap_from_s || t_s >= gap_to_s)) {
      GnssSample g;
      g.t = s.t;
      Eigen::Vector3d p = truth.Position(t_s);
      for (int i = 0; i < 3; ++i) p[i] += 0.02 * n01(rng);
      g.position = frame.ToLla(p);
      g.pos_std_enu_m.setConstant(0.02);
      g.fix_quality = 4;
      nav.Push(g);
    }
    nav.Push(s);
    nav.Update();
  }
  return {nav.stats(), (nav.Output().p_N_m - truth.Position(t_s)).head<2>().norm()};
}

// A walker (crab 8° ± 10°, sway ±5 cm at 1 Hz, bounce ±3 cm at 2 Hz): the constraint's innovations
// run far above their band while the fixes are there; its noise is raised to what they show, and
// the 10 s outage after a minute ends nearer the truth than with the constraint believed as
// configured.
TEST(NhcNoiseControlTest, AVehicleOutsideTheConstraintIsNoticed) {
  const Truth walker{1.2, 0.05, 8.0 * kPi / 180.0, 10.0 * kPi / 180.0, 0.05, 0.03};
  const DriveResult believed = Drive(walker, false, 60.0, 70.0);
  const DriveResult checked = Drive(walker, true, 60.0, 70.0);
  EXPECT_EQ(believed.stats.nhc_noise_raises, 0u);
  EXPECT_GT(checked.stats.nhc_noise_raises, 0u);
  EXPECT_GT(checked.stats.nhc_noise_scale, 4.0);
  EXPECT_LT(checked.end_error_m, 0.5 * believed.end_error_m)
      << "checked " << checked.end_error_m << " m, believed " << believed.end_error_m << " m";
  RecordProperty("outage_end_error_believed_checked_m",
                 std::to_string(believed.end_error_m) + " " + std::to_string(checked.end_error_m));
  RecordProperty("nhc_noise_scale", std::to_string(checked.stats.nhc_noise_scale));
}

// A vehicle that keeps to the constraint: the check never acts, the solution is the same.
TEST(NhcNoiseControlTest, AVehicleTheConstraintHoldsForIsUnchanged) {
  const Truth vehicle{1.2, 0.05};
  const DriveResult without = Drive(vehicle, false, 60.0, 70.0);
  const DriveResult with = Drive(vehicle, true, 60.0, 70.0);
  EXPECT_EQ(with.stats.nhc_noise_raises, 0u);
  EXPECT_EQ(with.stats.nhc_noise_scale, 1.0);
  EXPECT_EQ(with.end_error_m, without.end_error_m);
  EXPECT_LT(with.end_error_m, 0.5);
}

}  // namespace
}  // namespace hil::estimator

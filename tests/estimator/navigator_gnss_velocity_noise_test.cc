// The GNSS velocity's noise learned from its innovations (issue 39, paper 000's rig): a slow
// vehicle on a straight line, a receiver whose position error is time-correlated (τ 4.5 s) and
// whose Doppler velocity is better than the data sheet's σ the host configured (NMEA gives none).
// The IMU and the fixes are generated here with a seeded noise.
#include <chrono>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "hil/estimator/gnss_velocity_noise.h"
#include "hil/estimator/navigator.h"

#include "paper000_robot_params.h"

namespace hil::estimator {
namespace {

using namespace std::chrono_literals;

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
const Lla kOrigin{35.48, 50.60, 1312.0};
constexpr double kSpeed_mps = 0.45, kYaw_rad = 0.5;
constexpr double kGnssStd_m = 0.25, kGnssTau_s = 4.5;  // the receiver's correlated error

NavigatorParams Params(bool learn) {
  NavigatorParams p = test::Paper000RobotParams();
  p.gnss_vel_noise.enabled = learn;
  return p;
}

// Level vehicle on a straight line; IMU at 100 Hz, fixes at 1 Hz with HDOP 1.
struct Rig {
  Rig(const NavigatorParams& params, double vel_noise_mps, bool std_configured)
      : nav(params), vel_noise(vel_noise_mps), configured(std_configured) {
    nav.InitializeAt(kT0, kOrigin, Velocity(), Attitude());
  }
  static Eigen::Vector3d Velocity() {
    return Eigen::Vector3d(std::cos(kYaw_rad), std::sin(kYaw_rad), 0) * kSpeed_mps;
  }
  static Eigen::Quaterniond Attitude() {
    return Eigen::Quaterniond(Eigen::AngleAxisd(kYaw_rad, Eigen::Vector3d::UnitZ()));
  }
  // runs to t_end_s; sums the squared horizontal error at every fix from score_from_s on
  void Run(double t_end_s, double score_from_s) {
    const double dt = 0.01;
    const Eigen::Matrix3d C = Attitude().toRotationMatrix();
    const Eigen::Vector3d w_ie = frame.w_IE_N();
    const Eigen::Vector3d g_N(0, 0, -NormalGravity(kOrigin.lat_deg, kOrigin.height_m));
    const Eigen::Vector3d f_B = C.transpose() * (2.0 * w_ie.cross(Velocity()) - g_N);
    const Eigen::Vector3d w_B = C.transpose() * w_ie;
    const double phi = std::exp(-1.0 / kGnssTau_s);
    for (; t_s < t_end_s - 1e-9; ++k) {
      ImuSample s;
      t_s += dt;
      s.t = kT0 + Nanoseconds{std::llround(t_s * 1e9)};
      s.dt_s = dt;
      for (int i = 0; i < 3; ++i) {
        s.delta_velocity_B_mps[i] = f_B[i] * dt + 0.0125 * std::sqrt(dt) * n01(rng);
        s.delta_angle_B_rad[i] = w_B[i] * dt + 0.002 * std::sqrt(dt) * n01(rng);
      }
      if ((k + 1) % 100 == 0) {
        for (int i = 0; i < 2; ++i)
          error_N_m[i] = phi * error_N_m[i] + std::sqrt(1 - phi * phi) * kGnssStd_m * n01(rng);
        Fix(s.t);
        nav.Push(s);
        nav.Update();
        if (t_s >= score_from_s) {
          sum_sq += (nav.Output().p_N_m - Velocity() * t_s).head<2>().squaredNorm();
          ++scored;
        }
        continue;
      }
      nav.Push(s);
      nav.Update();
    }
  }
  void Fix(GpsTime t) {
    GnssSample g;
    g.t = t;
    g.position = frame.ToLla(Velocity() * t_s + error_N_m);
    g.pos_std_enu_m = {0.03, 0.03, 0.06};
    g.hdop = 1.0;
    g.has_velocity = true;
    g.vel_enu_mps = Velocity();
    for (int i = 0; i < 2; ++i) g.vel_enu_mps[i] += vel_noise * n01(rng);
    g.vel_std_enu_mps = {0.1, 0.1, 0.2};  // the data sheet's figure
    g.vel_std_configured = configured;
    nav.Push(g);
  }
  double Rmse() const { return std::sqrt(sum_sq / static_cast<double>(scored)); }

  Navigator nav;
  double vel_noise;
  bool configured;
  LocalTangentFrame frame{kOrigin};
  std::mt19937 rng{39};
  std::normal_distribution<double> n01{0.0, 1.0};
  Eigen::Vector3d error_N_m = Eigen::Vector3d::Zero();
  double t_s = 0, sum_sq = 0;
  long k = 0;
  int scored = 0;
};

TEST(GnssVelocityNoiseTest, EstimatesTheVelocityVarianceFromItsIncrements) {
  // GIVEN white velocity errors of 0.03 m/s at HDOP 1 seen at HDOP 1.5: increments of variance 2R
  GnssVelocityNoise noise;
  std::mt19937 rng(7);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double s = std::sqrt(2.0) * 0.03 * 1.5;
  EXPECT_DOUBLE_EQ(noise.Std(0.1, 1.5, 0.01), 0.1);  // nothing learned yet: the configured σ
  for (int i = 0; i < 2000; ++i) noise.AddIncrement(s * n01(rng), s * n01(rng), 0.1, 1.5);
  // THEN the estimate at HDOP 1 is the receiver's 0.03, and it scales with the HDOP
  EXPECT_NEAR(noise.std_at_hdop1_mps(), 0.03, 0.004);
  EXPECT_NEAR(noise.Std(0.1, 2.0, 0.01), 0.06, 0.008);
  // AND it is never above the configured σ nor below the floor
  EXPECT_DOUBLE_EQ(noise.Std(0.05, 4.0, 0.01), 0.05);
  EXPECT_DOUBLE_EQ(noise.Std(0.1, 0.5, 0.02), 0.02);
}

// Feeds a velocity error of σ 0.03 m/s, first-order with fix-to-fix correlation rho, as
// increments d_k = e_k − e_k−1 (the INS exact), the way the navigator does.
GnssVelocityNoise LearnFromIncrements(double rho, int fixes) {
  GnssVelocityNoise noise;
  std::mt19937 rng(11);
  std::normal_distribution<double> n01(0.0, 1.0);
  const double sigma = 0.03, drive = sigma * std::sqrt(1.0 - rho * rho);
  double e[2] = {sigma * n01(rng), sigma * n01(rng)}, prev_d[2] = {0, 0};
  for (int k = 0; k < fixes; ++k) {
    double d[2];
    for (int i = 0; i < 2; ++i) {
      const double next = rho * e[i] + drive * n01(rng);
      d[i] = next - e[i];
      e[i] = next;
    }
    noise.AddIncrement(d[0], d[1], 0.1, 1.0);
    if (k > 0) noise.AddIncrementLag(d[0], d[1], prev_d[0], prev_d[1], 0.1);
    prev_d[0] = d[0];
    prev_d[1] = d[1];
  }
  return noise;
}

TEST(GnssVelocityNoiseTest, ACorrelatedVelocityErrorIsNotTakenForASmallOne) {
  // GIVEN white velocity errors: the increments' variance is 2R, and the estimate is R
  const GnssVelocityNoise white = LearnFromIncrements(0.0, 3000);
  EXPECT_NEAR(white.one_minus_rho(), 1.0, 0.15);
  EXPECT_NEAR(white.std_at_hdop1_mps(), 0.03, 0.005);
  // WHEN the errors are correlated from fix to fix (a receiver that smooths its velocity), the
  // increments alone would read 0.03·√(1 − ρ): 0.013 m/s at ρ 0.8 (the increments' variance is
  // 2R(1 − ρ)); THEN the lag-1 correlation restores R
  const GnssVelocityNoise smoothed = LearnFromIncrements(0.6, 3000);
  EXPECT_NEAR(smoothed.one_minus_rho(), 0.4, 0.1);
  EXPECT_NEAR(smoothed.std_at_hdop1_mps(), 0.03, 0.006);
  // AND beyond ρ 0.8 nothing is learned: the configured σ holds
  const GnssVelocityNoise held = LearnFromIncrements(0.95, 3000);
  EXPECT_LT(held.one_minus_rho(), 0.2);
  EXPECT_DOUBLE_EQ(held.std_at_hdop1_mps(), 0.0);
  EXPECT_DOUBLE_EQ(held.Std(0.1, 1.0, 0.01), 0.1);
}

TEST(GnssVelocityNoiseTest, AGlitchIsClipped) {
  GnssVelocityNoise clean, glitched;
  for (int i = 0; i < 60; ++i) {
    clean.AddIncrement(0.03, -0.03, 0.1, 1.0);
    // one wild velocity (50 m/s off) counts as at most 3σ of the configured 0.1 m/s
    if (i == 30)
      glitched.AddIncrement(50.0, 50.0, 0.1, 1.0);
    else
      glitched.AddIncrement(0.03, -0.03, 0.1, 1.0);
  }
  EXPECT_LT(clean.std_at_hdop1_mps(), 0.05);
  EXPECT_LT(glitched.std_at_hdop1_mps(), 0.1);  // unclipped it would be metres per second
  EXPECT_GT(glitched.std_at_hdop1_mps(), clean.std_at_hdop1_mps());
}

TEST(NavigatorGnssVelocityNoiseTest, LearnsAnNmeaVelocityBetterThanConfigured) {
  // GIVEN NMEA fixes whose velocity is good to 0.03 m/s, configured at the data sheet's 0.1 m/s
  Rig learned(Params(true), 0.03, true);
  learned.Run(300, 60);
  Rig fixed(Params(false), 0.03, true);
  fixed.Run(300, 60);
  // THEN the filter fuses them with about the σ they have: above it rather than below, since the
  // INS increment's own error (accelerometer noise, tilt) enters the increments' variance and
  // their lag-1 correlation on the safe side
  EXPECT_TRUE(learned.nav.stats().gnss_vel_std_learned);
  EXPECT_GT(learned.nav.stats().gnss_vel_std_mps, 0.025);
  EXPECT_LT(learned.nav.stats().gnss_vel_std_mps, 0.06);
  EXPECT_DOUBLE_EQ(fixed.nav.stats().gnss_vel_std_mps, 0.1);
  // AND averages the receiver's correlated position error better than at the configured σ
  EXPECT_LT(learned.Rmse(), 0.9 * fixed.Rmse()) << learned.Rmse() << " vs " << fixed.Rmse();
}

TEST(NavigatorGnssVelocityNoiseTest, KeepsAReportedOrAWorseSigma) {
  // a receiver's own velocity accuracy (UBX sAcc) is used as it is
  Rig reported(Params(true), 0.03, false);
  reported.Run(120, 60);
  EXPECT_DOUBLE_EQ(reported.nav.stats().gnss_vel_std_mps, 0.1);
  EXPECT_FALSE(reported.nav.stats().gnss_vel_std_learned);
  // a velocity worse than configured is not widened (the IMU noise check reads its innovations)
  Rig worse(Params(true), 0.3, true);
  worse.Run(120, 60);
  EXPECT_DOUBLE_EQ(worse.nav.stats().gnss_vel_std_mps, 0.1);
}

}  // namespace
}  // namespace hil::estimator

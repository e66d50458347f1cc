// VehicleVelocityRipple (vehicle_velocity_ripple.h): the ripple the INS's propagation carries above
// a critically damped low-pass, and the speed model that leaves it out (ErrorStateEkf,
// `vehicle_lowpass_tau_s`).
#include "hil/estimator/vehicle_velocity_ripple.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hil/estimator/error_state_ekf.h"

namespace hil::estimator {
namespace {

constexpr double kDt = 0.01;  // 100 Hz, as the tractor rig's IMU
constexpr double kG = 9.80665;

// A forward velocity ripple of amplitude `amp_mps` at `f_hz` on top of a slow speed change of
// `accel_mps2`: the largest |velocity − its low-pass| (v − ripple) over the last `window_s`.
double ResidualAfter(VehicleVelocityRipple& r, double amp_mps, double f_hz, double accel_mps2,
                     double seconds, double window_s) {
  const double w = 2 * M_PI * f_hz;
  double v_prev = 0, worst = 0;
  for (int k = 1; k <= static_cast<int>(seconds / kDt); ++k) {
    const double t = k * kDt;
    const double v = amp_mps * std::sin(w * t) + accel_mps2 * t;
    r.Propagate(Eigen::Vector3d(v - v_prev, 0, 0), kDt);
    v_prev = v;
    // what the speed model sees of the ripple: v − x2 = lp2(v), less the slow speed's lag 2τ·a
    const double slow = accel_mps2 * t;
    if (t > seconds - window_s) worst = std::max(worst, std::abs(v - r.ripple_V_mps().x() - slow));
  }
  return worst;
}

TEST(VehicleVelocityRipple, LeavesOutARideSinusoid) {
  VehicleVelocityRipple r(0.5);
  // |lp2| = 1 / (1 + (2π f τ)²): 0.092 at 1 Hz, 0.043 at 1.5 Hz
  EXPECT_LT(ResidualAfter(r, 0.03, 1.0, 0.0, 20.0, 5.0), 0.0935 * 0.03 + 1e-4);
  r.Reset();
  EXPECT_LT(ResidualAfter(r, 0.03, 1.5, 0.0, 20.0, 5.0), 0.044 * 0.03 + 1e-4);
}

TEST(VehicleVelocityRipple, PassesASlowSpeedChangeWithItsLag) {
  VehicleVelocityRipple r(0.5);
  // a steady 0.01 m/s² is seen 2τ late: 2 · 0.5 s · 0.01 = 0.01 m/s behind
  const double lagged = ResidualAfter(r, 0.0, 1.0, 0.01, 20.0, 5.0);
  EXPECT_NEAR(lagged, 2 * 0.5 * 0.01, 1e-4);
}

TEST(VehicleVelocityRipple, OffStaysZero) {
  VehicleVelocityRipple r(0.0);
  EXPECT_FALSE(r.enabled());
  r.Propagate(Eigen::Vector3d(0.1, 0.2, 0.3), kDt);
  EXPECT_EQ(r.ripple_V_mps(), Eigen::Vector3d::Zero());
}

// A straight line at 1 m/s while the body surges (true motion: the IMU senses it, the INS
// integrates it exactly; two sinusoids of the ride band, 2.6 cm/s r.m.s. of velocity as on the
// tractor's capture): 60 s with 10 Hz position fixes (1 cm), then 10 s without. The speed model and
// the NHC run at 10 Hz as on the tractor rig. Returns the largest along-track position error of the
// outage, m.
struct Surge {
  double amp_mps2, w_radps, phase_rad;
};
constexpr Surge kSurge[] = {{0.25, 2 * M_PI * 1.3, 0.0}, {0.3, 2 * M_PI * 2.1, 1.0}};

double SurgeVelocity(double t) {
  double v = 0;
  for (const Surge& s : kSurge) v += s.amp_mps2 / s.w_radps * std::sin(s.w_radps * t + s.phase_rad);
  return v;
}
double SurgeDisplacement(double t) {
  double x = 0;
  for (const Surge& s : kSurge)
    x -= s.amp_mps2 / (s.w_radps * s.w_radps) * std::cos(s.w_radps * t + s.phase_rad);
  return x;
}

double OutageErrorAlongTrack(double lowpass_tau_s) {
  EkfParams p;
  p.accel_noise_mps2_rthz = 0.003;
  p.gyro_noise_radps_rthz = 1.5e-4;
  p.accel_bias_rw_mps3_rthz = 1e-4;
  p.gyro_bias_rw_radps2_rthz = 1e-6;
  p.nhc_std_mps = 0.02;
  p.speed_rw_mps_rthz = 0.009;
  p.speed_dev_std_mps = 0.005;
  p.init_pos_std_m = 0.01;
  p.init_vel_std_mps = 0.05;
  p.init_roll_pitch_std_rad = 1e-3;
  p.init_yaw_std_rad = 1e-3;
  p.init_accel_bias_std_mps2 = 1e-3;
  p.vehicle_lowpass_tau_s = lowpass_tau_s;
  ErrorStateEkf ekf(p, EarthModel{});
  NavState s;
  s.p_N_m.x() = SurgeDisplacement(0);
  s.v_N_mps = Eigen::Vector3d(1.0 + SurgeVelocity(0), 0.0, 0.0);  // heading east: body x = east
  ekf.Initialize(s);
  double worst = 0;
  for (int k = 1; k <= 7000; ++k) {
    const double t0 = (k - 1) * kDt, t1 = k * kDt;
    const double x_true = t1 + SurgeDisplacement(t1);
    // the exact velocity increment of the surge over the step, plus gravity's reaction on z
    const double dvx = SurgeVelocity(t1) - SurgeVelocity(t0);
    ekf.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(dvx, 0.0, kG * kDt), kDt);
    if (k % 10 != 0) continue;
    ekf.UpdateNonHolonomic();
    ekf.UpdateSpeedModel();
    if (t1 <= 60.0 + 1e-9) {
      ekf.UpdatePosition(Eigen::Vector3d(x_true, 0, 0), Eigen::Vector3d::Constant(0.01));
    } else {
      worst = std::max(worst, std::abs(ekf.state().p_N_m.x() - x_true));
    }
  }
  return worst;
}

TEST(VehicleVelocityRipple, TheSpeedModelLeavesTheSurgeAloneInAnOutage) {
  const double plain = OutageErrorAlongTrack(0.0);
  const double lowpassed = OutageErrorAlongTrack(0.5);
  // instantaneous: each update takes the ripple for a velocity error and, P_pv ≈ t·P_vv, moves
  // the position by up to t × it (4.5 cm here); low-passed: what is left is the ripple's residual
  // (lp2 at 1.3 Hz: 0.057 of it; 6.7 mm here)
  EXPECT_GT(plain, 0.03) << "plain " << plain;
  EXPECT_LT(lowpassed, 0.01) << "low-passed " << lowpassed;
}

}  // namespace
}  // namespace hil::estimator

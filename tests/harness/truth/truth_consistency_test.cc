// Self-consistency of the truth: its own body rates and specific forces, integrated by an
// independent strapdown, reproduce its trajectory; and it is converged in the CVODE tolerance.
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "hil/truth/truth_integrator.h"

#include "truth_test_scenarios.h"

namespace hil::truth {
namespace {

// A strapdown state in the Earth-fixed frame N.
struct Nav {
  Eigen::Vector3d p, v;
  Eigen::Quaterniond q;  // B → N
};
struct NavRate {
  Eigen::Vector3d p_dot, v_dot;
  Eigen::Vector4d q_dot;  // (w, x, y, z)
};

// ṗ = v, v̇ = R f + g(p) − 2Ω×v, q̇ = ½ q ⊗ (ω_IB − Rᵀ Ω)
NavRate Rates(const LocalFrame& frame, const Eigen::Vector3d& w_IE_N, const Nav& x,
              const Eigen::Vector3d& f_B, const Eigen::Vector3d& w_IB_B) {
  const Eigen::Matrix3d R = x.q.toRotationMatrix();
  NavRate r;
  r.p_dot = x.v;
  r.v_dot = R * f_B + GravityAt(frame, x.p) - 2 * w_IE_N.cross(x.v);
  const Eigen::Vector3d w = w_IB_B - R.transpose() * w_IE_N;
  const Eigen::Quaterniond dq = x.q * Eigen::Quaterniond(0, w.x(), w.y(), w.z());
  r.q_dot = 0.5 * Eigen::Vector4d(dq.w(), dq.x(), dq.y(), dq.z());
  return r;
}

Nav Add(const Nav& x, const NavRate& r, double h) {
  Nav y;
  y.p = x.p + h * r.p_dot;
  y.v = x.v + h * r.v_dot;
  y.q = Eigen::Quaterniond(x.q.w() + h * r.q_dot[0], x.q.x() + h * r.q_dot[1],
                           x.q.y() + h * r.q_dot[2], x.q.z() + h * r.q_dot[3]);
  return y;
}

TEST(TruthConsistencyTest, StrapdownOfOwnImuTruthAt1kHzStaysWithin1mmOver60s) {
  // GIVEN the rough-terrain, turning, vibrating scenario, sampled at 1 kHz
  const TruthConfig c = testing::RoughTurningConfig();
  TruthIntegrator truth(c);
  const Eigen::Vector3d w_IE_N = EarthRateIn(truth.frame());
  const TruthSample s0 = truth.Sample(Time{});
  Nav x{s0.p_NB_N_m, s0.v_NB_N_mps, s0.q_NB};
  TruthSample a = s0;
  double max_err = 0, max_att = 0;
  double roll_span = 0, pitch_span = 0, yaw_rate_max = 0;
  // WHEN RK4 with 2 ms steps integrates the truth's specific force and inertial rate (stages at
  // the 1 kHz samples t, t + 1 ms, t + 2 ms)
  for (int k = 0; k < 60000; k += 2) {
    const TruthSample b = truth.Sample(TimeFromNs((k + 1) * 1'000'000LL));
    const TruthSample e = truth.Sample(TimeFromNs((k + 2) * 1'000'000LL));
    const double h = 2e-3;
    const NavRate k1 = Rates(truth.frame(), w_IE_N, x, a.f_B_mps2, a.w_IB_B_radps);
    const NavRate k2 = Rates(truth.frame(), w_IE_N, Add(x, k1, h / 2), b.f_B_mps2, b.w_IB_B_radps);
    const NavRate k3 = Rates(truth.frame(), w_IE_N, Add(x, k2, h / 2), b.f_B_mps2, b.w_IB_B_radps);
    const NavRate k4 = Rates(truth.frame(), w_IE_N, Add(x, k3, h), e.f_B_mps2, e.w_IB_B_radps);
    NavRate sum;
    sum.p_dot = (k1.p_dot + 2 * k2.p_dot + 2 * k3.p_dot + k4.p_dot) / 6;
    sum.v_dot = (k1.v_dot + 2 * k2.v_dot + 2 * k3.v_dot + k4.v_dot) / 6;
    sum.q_dot = (k1.q_dot + 2 * k2.q_dot + 2 * k3.q_dot + k4.q_dot) / 6;
    x = Add(x, sum, h);
    x.q.normalize();
    a = e;
    max_err = std::max(max_err, (x.p - e.p_NB_N_m).norm());
    max_att = std::max(max_att, Eigen::AngleAxisd(x.q.conjugate() * e.q_NB).angle());
    const Eigen::Matrix3d R = e.q_NB.toRotationMatrix();
    roll_span = std::max(roll_span, std::abs(std::asin(R(2, 1))));
    pitch_span = std::max(pitch_span, std::abs(std::asin(R(2, 0))));
    yaw_rate_max = std::max(yaw_rate_max, std::abs(e.w_NB_B_radps.z()));
  }
  std::printf(
      "strapdown vs truth over 60 s: max position error %.3g m, max attitude error %.3g rad\n",
      max_err, max_att);
  std::printf("scenario: max |roll| %.2f deg, max |pitch| %.2f deg, max |yaw rate| %.1f deg/s\n",
              roll_span * 57.29578, pitch_span * 57.29578, yaw_rate_max * 57.29578);
  // THEN the strapdown follows the truth to well below a millimetre
  EXPECT_LT(max_err, 1e-3);
  // and the scenario really exercised roll, pitch and turning
  EXPECT_GT(roll_span, 0.5 / 57.3);
  EXPECT_GT(pitch_span, 0.5 / 57.3);
  EXPECT_GT(yaw_rate_max, 10 / 57.3);
}

TEST(TruthConsistencyTest, TruthAtRtolAndRtolOver100DiffersByLessThan0p1mm) {
  TruthConfig coarse = testing::RoughTurningConfig();
  coarse.rtol = 1e-9;
  coarse.atol_m = 1e-8;
  TruthConfig fine = coarse;
  fine.rtol = coarse.rtol / 100;
  fine.atol_m = coarse.atol_m / 100;
  TruthIntegrator a(coarse), b(fine);
  double max_diff = 0, max_f_diff = 0;
  for (int k = 0; k <= 1200; ++k) {
    const Time t = TimeFromNs(k * 100'000'000LL);
    const TruthSample sa = a.Sample(t), sb = b.Sample(t);
    max_diff = std::max(max_diff, (sa.p_NB_N_m - sb.p_NB_N_m).norm());
    max_f_diff = std::max(max_f_diff, (sa.f_B_mps2 - sb.f_B_mps2).norm());
  }
  std::printf(
      "rtol %.0e vs %.0e over 120 s: max position difference %.3g m, max specific-force difference "
      "%.3g m/s^2 "
      "(steps %ld vs %ld)\n",
      coarse.rtol, fine.rtol, max_diff, max_f_diff, a.steps(), b.steps());
  EXPECT_LT(max_diff, 1e-4);
}

}  // namespace
}  // namespace hil::truth

// Measurement models of the error-state EKF against finite differences of the measurement
// functions, and gating/consistency behaviour of the update.
#include "hil/estimator/error_state_ekf.h"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

using namespace ekf_index;

// Central differences of a measurement function h(filter) over the injected error state.
template <int M, typename F>
Eigen::Matrix<double, M, kNumStates> NumericJacobian(const ErrorStateEkf& at, F h) {
  Eigen::Matrix<double, M, kNumStates> J;
  const double eps = 1e-6;
  for (int i = 0; i < kNumStates; ++i) {
    ErrorStateEkf plus = at, minus = at;
    EkfVector dx = EkfVector::Zero();
    dx[i] = eps;
    plus.InjectError(dx);
    minus.InjectError(-dx);
    J.col(i) = (h(plus) - h(minus)) / (2 * eps);
  }
  return J;
}

class ErrorStateEkfTest : public ::testing::Test {
 protected:
  void SetUp() override {
    EkfParams p;
    p.lever_arm_B_m = Eigen::Vector3d(0.8, -0.3, 1.5);
    p.gnss_error_tau_s = 5.0;
    p.gnss_error_std_m = 0.3;
    p.nhc_std_mps = 0.05;
    p.speed_rw_mps_rthz = 0.001;
    p.gyro_z_coupling_x_std_rad =
        0.005;  // the x and y gyros' coupling states on (x off by default)
    p.gyro_z_coupling_y_std_rad = 0.005;
    p.gyro_scale_xy_std = 0.005;  // the x and y gyros' scale states on (off by default)
    ekf_ = ErrorStateEkf(p, EarthModel{});
    NavState s;
    s.p_N_m = Eigen::Vector3d(10, -4, 2);
    s.v_N_mps = Eigen::Vector3d(2.4, 0.8, -0.1);  // above 2 m/s: the residual lag is learned
    s.q_NB = Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()) *
             Eigen::AngleAxisd(-0.03, Eigen::Vector3d::UnitX());
    ekf_.Initialize(s);
    // one interval so the filter has an angular rate (for the lever-arm velocity)
    raw_w_ = Eigen::Vector3d(0.02, -0.01, 0.3);
    ekf_.Predict(raw_w_ * 0.01, Eigen::Vector3d(0.1, 0.0, 9.81) * 0.01, 0.01);
  }
  // measurement functions of the nominal state, written out independently of the filter
  // the fix sees the antenna the residual tag lag δt later: moved on by its velocity times δt
  Eigen::Vector3d Pos(const ErrorStateEkf& e) const {
    return e.state().p_N_m + e.state().q_NB * e.params().lever_arm_B_m + e.gnss_error() +
           AntennaVel(e) * e.imu_time_residual_s();
  }
  Eigen::Vector3d AntennaVel(const ErrorStateEkf& e) const {
    // the rate the filter used, re-derived from the bias, the z gyro's scale, the x and y
    // gyros' coupling to the z rate and their scales
    Eigen::Vector3d w = raw_w_ - e.gyro_bias();
    w.z() /= 1.0 + e.gyro_scale_z();
    w.head<2>() -= e.gyro_z_coupling_rad() * w.z();
    w.head<2>().array() /= 1.0 + e.gyro_scale_xy().array();
    return e.state().v_N_mps + e.state().q_NB * w.cross(e.params().lever_arm_B_m);
  }
  // and its velocity changed by the (smoothed) acceleration times δt
  Eigen::Vector3d Vel(const ErrorStateEkf& e) const {
    return AntennaVel(e) + e.smoothed_acceleration_N() * e.imu_time_residual_s();
  }
  // the vehicle-frame velocity: the body velocity turned by the mounting angles, C_VB = Exp(μ)ᵀ
  static Eigen::Vector3d VehicleVelocity(const ErrorStateEkf& e) {
    return QuatFromRotationVector(e.mount_angles_rad()).conjugate() *
           (e.state().q_NB.conjugate() * e.state().v_N_mps);
  }
  static double Speed(const ErrorStateEkf& e) { return VehicleVelocity(e).x() - e.set_speed_mps(); }
  static Eigen::Vector2d Nhc(const ErrorStateEkf& e) { return VehicleVelocity(e).tail<2>(); }
  template <int M, typename F>
  Eigen::Matrix<double, M, kNumStates> Numeric(F h) const {
    return NumericJacobian<M>(ekf_, h);
  }
  ErrorStateEkf ekf_;
  Eigen::Vector3d raw_w_;
};

TEST_F(ErrorStateEkfTest, PositionJacobianMatchesFiniteDifferences) {
  const auto J = Numeric<3>([this](const ErrorStateEkf& e) { return Pos(e); });
  EXPECT_LT((J - ekf_.PositionJacobian()).cwiseAbs().maxCoeff(), 1e-6) << J << "\n\n"
                                                                       << ekf_.PositionJacobian();
}

TEST_F(ErrorStateEkfTest, VelocityJacobianMatchesFiniteDifferences) {
  // the gyro rate seen by the lever arm is held at the sample's (bias-corrected) value
  const Eigen::Vector3d expected_rate = raw_w_ - ekf_.gyro_bias();
  ASSERT_LT((ekf_.last_gyro_rate_B() - expected_rate).norm(), 1e-9);
  // the couplings' columns are the turns' only at speed after a fix (TurnStatesLearnable): a fix
  // where the filter predicts it (no correction, the state unchanged)
  ekf_.UpdatePosition(Pos(ekf_), Eigen::Vector3d::Constant(0.05));
  const auto J = Numeric<3>([this](const ErrorStateEkf& e) { return Vel(e); });
  EXPECT_LT((J - ekf_.VelocityJacobian()).cwiseAbs().maxCoeff(), 1e-6) << J << "\n\n"
                                                                       << ekf_.VelocityJacobian();
}

TEST_F(ErrorStateEkfTest, NonHolonomicJacobianMatchesFiniteDifferences) {
  const auto J = Numeric<2>([](const ErrorStateEkf& e) { return Nhc(e); });
  EXPECT_LT((J - ekf_.NonHolonomicJacobian()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_F(ErrorStateEkfTest, SpeedModelJacobianMatchesFiniteDifferences) {
  const auto J =
      Numeric<1>([](const ErrorStateEkf& e) { return Eigen::Matrix<double, 1, 1>(Speed(e)); });
  EXPECT_LT((J - ekf_.SpeedModelJacobian()).cwiseAbs().maxCoeff(), 1e-6)
      << J << "\n\n"
      << ekf_.SpeedModelJacobian();
}

TEST_F(ErrorStateEkfTest, SpeedModelPullsTheForwardSpeedToTheSetSpeed) {
  // GIVEN the set speed started at the current forward speed, then a forward-speed error of 0.1 m/s
  ekf_.ResetSetSpeed(0.01);
  const double set = ekf_.set_speed_mps();
  ekf_.mutable_state().v_N_mps += ekf_.state().q_NB * Eigen::Vector3d(0.1, 0, 0);
  // WHEN the speed model is applied
  const UpdateResult r = ekf_.UpdateSpeedModel();
  // THEN it is accepted and moves the forward speed most of the way back (set speed σ 0.01 <
  // velocity σ)
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(r.dof, 1);
  EXPECT_LT(std::abs(Speed(ekf_)), 0.03);
  EXPECT_LT(std::abs(ekf_.set_speed_mps() - set), 0.03);
}

TEST_F(ErrorStateEkfTest, GateRejectsAnOutlierAndAcceptsAConsistentFix) {
  const Eigen::Vector3d p = Pos(ekf_);
  const UpdateResult bad =
      ekf_.UpdatePosition(p + Eigen::Vector3d(50, 0, 0), Eigen::Vector3d::Constant(0.1));
  EXPECT_FALSE(bad.accepted);
  EXPECT_GT(bad.nis, 25.0 * 3);
  const UpdateResult good =
      ekf_.UpdatePosition(p + Eigen::Vector3d(0.2, -0.1, 0.1), Eigen::Vector3d::Constant(0.1));
  EXPECT_TRUE(good.accepted);
  EXPECT_LT((Pos(ekf_) - (p + Eigen::Vector3d(0.2, -0.1, 0.1))).norm(), 0.2);
}

// issue 39: the fading factor of a rejected fix, applied, makes that fix consistent
TEST_F(ErrorStateEkfTest, FadingByTheExcessFactorMakesARejectedFixAcceptable) {
  const Eigen::Vector3d p = Pos(ekf_) + Eigen::Vector3d(8, -6, 3);
  ErrorStateEkf faded = ekf_;
  const UpdateResult bad = faded.UpdatePosition(p, Eigen::Vector3d::Constant(0.1));
  ASSERT_FALSE(bad.accepted);
  EXPECT_GT(bad.excess, 10.0);
  const EkfMatrix before = faded.covariance();
  faded.InflateCovariance(bad.excess);
  // the classic block scales by λ (biases up to their initial variance), its cross terms with the
  // augmented states by √λ, the rest not
  EXPECT_NEAR(faded.covariance()(kAtt + 2, kPos), before(kAtt + 2, kPos) * bad.excess, 1e-12);
  EXPECT_NEAR(faded.covariance()(kPos, kGnssError),
              before(kPos, kGnssError) * std::sqrt(bad.excess), 1e-12);
  EXPECT_EQ(faded.covariance()(kGnssError, kGnssError), before(kGnssError, kGnssError));
  const UpdateResult retry = faded.UpdatePosition(p, Eigen::Vector3d::Constant(0.1));
  EXPECT_TRUE(retry.accepted);
  EXPECT_LT(retry.nis, 25.0 * 3);
}

// Fading never leaves a bias less known than its initial σ (a huge λ on a fix far off).
TEST_F(ErrorStateEkfTest, FadingCapsTheBiasVariancesAtTheirInitialOnes) {
  const EkfMatrix before = ekf_.covariance();
  ekf_.InflateCovariance(1e6);
  const EkfMatrix& P = ekf_.covariance();
  const EkfParams& p = ekf_.params();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(P(kAccelBias + i, kAccelBias + i), std::pow(p.init_accel_bias_std_mps2, 2), 1e-15);
    EXPECT_NEAR(P(kGyroBias + i, kGyroBias + i), std::pow(p.init_gyro_bias_std_radps, 2), 1e-15);
  }
  EXPECT_NEAR(P(kPos, kPos), before(kPos, kPos) * 1e6, 1e-6);
  // still a covariance: symmetric, positive semi-definite
  EXPECT_TRUE(P.isApprox(P.transpose()));
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<EkfMatrix>(P).eigenvalues().minCoeff(),
            -1e-12 * P.diagonal().maxCoeff());
}

// issue 39: a standing body's mean raw rate is the gyro bias plus the Earth's rate
TEST(ErrorStateEkfStandstillTest, ZeroAngularRateEstimatesTheGyroBiasAndHoldHoldsTheAttitude) {
  EarthModel earth;
  earth.w_IE_N_radps = Eigen::Vector3d(0, 7.292115e-5 * std::cos(0.8), 7.292115e-5 * std::sin(0.8));
  earth.g_N_mps2 = Eigen::Vector3d(0, 0, -9.81);
  ErrorStateEkf ekf(EkfParams{}, earth);
  NavState s;
  s.q_NB = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
  ekf.Initialize(s);
  const Eigen::Vector3d bias(1e-3, -2e-3, 5e-4);
  const Eigen::Vector3d raw = bias + s.q_NB.conjugate() * earth.w_IE_N_radps;
  ekf.SetAttitudeHold(true);
  for (int k = 0; k < 200; ++k) {
    ekf.Predict(raw * 0.01, Eigen::Vector3d(0, 0, 9.81) * 0.01, 0.01);
    if (k % 50 == 49) {
      EXPECT_TRUE(ekf.UpdateZeroAngularRate(raw, 1e-5).accepted);
      EXPECT_TRUE(ekf.UpdateZeroVelocity(0.01).accepted);
    }
  }
  EXPECT_LT((ekf.gyro_bias() - bias).norm(), 1e-5);
  // held: the attitude turned with the Earth only, not by the (biased) gyro
  EXPECT_LT(Eigen::AngleAxisd(ekf.state().q_NB.conjugate() * s.q_NB).angle(), 1e-6);
  EXPECT_LT(ekf.state().v_N_mps.norm(), 0.01);
}

// issue 39: while held, the nominal attitude turns with the Earth exactly as the standing body
// does, so the attitude error does not move: four hours of prediction leave its covariance as it
// was (before, the error was rotated by the Earth's rate, −[ω_IE×]φ, about 1 rad in 4 h, which
// turned the unobservable tilt of a parked vehicle into heading and shrank its variance without
// cause).
TEST(ErrorStateEkfStandstillTest, HeldAttitudeErrorDoesNotTurnWithTheEarth) {
  EarthModel earth;
  earth.w_IE_N_radps = Eigen::Vector3d(0, 7.292115e-5 * std::cos(0.8), 7.292115e-5 * std::sin(0.8));
  earth.g_N_mps2 = Eigen::Vector3d(0, 0, -9.81);
  EkfParams p;
  p.init_roll_pitch_std_rad = 0.02;
  p.init_yaw_std_rad = 0.3;
  ErrorStateEkf ekf(p, earth);
  NavState s;
  s.q_NB = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
  ekf.Initialize(s);
  const Eigen::Matrix3d att_before = ekf.covariance().block<3, 3>(kAtt, kAtt);
  const Eigen::Vector3d raw_rate = s.q_NB.conjugate() * earth.w_IE_N_radps;
  ekf.SetAttitudeHold(true);
  for (int k = 0; k < 4 * 3600; ++k)
    ekf.Predict(raw_rate * 1.0, s.q_NB.conjugate() * Eigen::Vector3d(0, 0, 9.81), 1.0);
  const Eigen::Matrix3d att_after = ekf.covariance().block<3, 3>(kAtt, kAtt);
  EXPECT_LT((att_after - att_before).cwiseAbs().maxCoeff(), 1e-12) << "before\n"
                                                                   << att_before << "\nafter\n"
                                                                   << att_after;
}

// issue 39 (parked_for_hours): a half turn on a gyro with a scale or misalignment error s leaves
// an attitude error of about s·π, which the white angle random walk alone did not hold (the turn
// taught the filter a tilt 0.3-0.5° off with a σ of about 0.12°); a straight drive adds nothing.
TEST(ErrorStateEkfTurnTest, AttitudeVarianceGrowsWithTheAngleTurned) {
  EkfParams p;
  p.gyro_noise_radps_rthz = 1e-6;
  p.gyro_scale_std = 0.005;
  p.init_gyro_bias_std_radps = 1e-6;  // no other source of attitude variance
  const auto roll_var_after = [&p](double rate_radps) {
    ErrorStateEkf ekf(p, EarthModel{});
    ekf.Initialize(NavState{});
    const double before = ekf.covariance()(kAtt, kAtt);
    for (int k = 0; k < 1000; ++k)  // 10 s at 100 Hz
      ekf.Predict(Eigen::Vector3d(0, 0, rate_radps * 0.01), Eigen::Vector3d(0, 0, 9.81) * 0.01,
                  0.01);
    return ekf.covariance()(kAtt, kAtt) - before;
  };
  const double s_pi = p.gyro_scale_std * std::numbers::pi;
  EXPECT_GT(roll_var_after(std::numbers::pi / 10.0), 0.9 * s_pi * s_pi);
  EXPECT_LT(roll_var_after(0.0), 1e-9);
}

TEST_F(ErrorStateEkfTest, NonFiniteInputsAreIgnored) {
  const NavState before = ekf_.state();
  ekf_.Predict(Eigen::Vector3d::Constant(std::nan("")), Eigen::Vector3d::Zero(), 0.01);
  EXPECT_FALSE(
      ekf_.UpdatePosition(Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Ones()).accepted);
  EXPECT_EQ(ekf_.state().p_N_m, before.p_N_m);
  EXPECT_TRUE(ekf_.covariance().allFinite());
}

// The speed model with a deviation state (speed_dev_tau_s > 0): forward speed = set speed + d, d a
// first-order Gauss–Markov process.
class ErrorStateEkfSpeedDevTest : public ::testing::Test {
 protected:
  void SetUp() override {
    EkfParams p;
    p.speed_rw_mps_rthz = 0.0005;
    p.speed_dev_std_mps = 0.02;
    p.speed_dev_tau_s = 5.0;
    ekf_ = ErrorStateEkf(p, EarthModel{});
    NavState s;
    s.v_N_mps = Eigen::Vector3d(0.3, 0.9, 0.0);
    s.q_NB = Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitY());
    ekf_.Initialize(s);
  }
  double P(int i) const { return ekf_.covariance()(i, i); }
  static double Residual(const ErrorStateEkf& e) {
    return (e.state().q_NB.conjugate() * e.state().v_N_mps).x() - e.set_speed_mps() -
           e.speed_deviation_mps();
  }
  ErrorStateEkf ekf_;
};

TEST_F(ErrorStateEkfSpeedDevTest, JacobianMatchesFiniteDifferences) {
  const auto J = NumericJacobian<1>(
      ekf_, [](const ErrorStateEkf& e) { return Eigen::Matrix<double, 1, 1>(Residual(e)); });
  EXPECT_LT((J - ekf_.SpeedModelJacobian()).cwiseAbs().maxCoeff(), 1e-6)
      << J << "\n\n"
      << ekf_.SpeedModelJacobian();
  EXPECT_DOUBLE_EQ(ekf_.SpeedModelJacobian()(0, kSpeedDev), -1.0);
}

TEST_F(ErrorStateEkfSpeedDevTest, DeviationDecaysAndItsVarianceIsStationary) {
  // GIVEN a deviation of 0.02 m/s
  EkfVector dx = EkfVector::Zero();
  dx[kSpeedDev] = 0.02;
  ekf_.InjectError(dx);
  EXPECT_NEAR(P(kSpeedDev), 0.02 * 0.02, 1e-15);  // starts at its stationary variance
  // WHEN 10 s (two correlation times) pass without measurements
  for (int k = 0; k < 1000; ++k)
    ekf_.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 9.81) * 0.01, 0.01);
  // THEN it has decayed by e^-2 and its variance stayed at σ²
  EXPECT_NEAR(ekf_.speed_deviation_mps(), 0.02 * std::exp(-2.0), 1e-12);
  EXPECT_NEAR(P(kSpeedDev), 0.02 * 0.02, 1e-9);
}

TEST_F(ErrorStateEkfSpeedDevTest, ASpeedChangeGoesToTheDeviationNotTheSetSpeed) {
  // GIVEN a vehicle heading along its velocity, a converged set speed (σ 2 mm/s) and a forward
  // speed 0.02 m/s above it, held by velocity fixes
  NavState aligned;
  aligned.v_N_mps = Eigen::Vector3d(0.3, 0.9, 0.0);
  aligned.q_NB = Eigen::AngleAxisd(std::atan2(0.9, 0.3), Eigen::Vector3d::UnitZ());
  ekf_.Initialize(aligned);
  ekf_.ResetSetSpeed(0.002);
  const double set = ekf_.set_speed_mps();
  const Eigen::Vector3d v = ekf_.state().v_N_mps + ekf_.state().q_NB * Eigen::Vector3d(0.02, 0, 0);
  for (int k = 0; k < 200; ++k) {  // 2 s at 100 Hz
    ekf_.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 9.81) * 0.01, 0.01);
    ekf_.UpdateVelocity(v, Eigen::Vector3d::Constant(0.005));
    ekf_.UpdateSpeedModel();
  }
  // THEN the deviation explains the difference and the set speed barely moves
  EXPECT_NEAR(ekf_.speed_deviation_mps(), 0.02, 0.004);
  EXPECT_LT(std::abs(ekf_.set_speed_mps() - set), 0.002);
  EXPECT_LT(std::abs(Residual(ekf_)), 0.003);
}

TEST_F(ErrorStateEkfTest, GnssErrorModelSwitchAddsOrRestartsTheCorrelatedError) {
  // GIVEN a filter whose correlated GNSS error state has been observed (cross-covariances built up)
  const Eigen::Vector3d p = Pos(ekf_);
  ASSERT_TRUE(
      ekf_.UpdatePosition(p + Eigen::Vector3d(0.05, -0.02, 0.0), Eigen::Vector3d::Constant(0.05))
          .accepted);
  const EkfMatrix before = ekf_.covariance();
  const double cross_before = before.block<3, 3>(kPos, kGnssError).cwiseAbs().maxCoeff();
  ASSERT_GT(cross_before, 1e-4);
  // WHEN the receiver drops to RTK float (a larger, independent error appears)
  ekf_.SetGnssErrorModel(2.0, 0.5, true);
  const EkfMatrix wider = ekf_.covariance();
  // THEN its variance grows by σ_new² − σ_old² and nothing else changes
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(wider(kGnssError + i, kGnssError + i) - before(kGnssError + i, kGnssError + i),
                0.25 - 0.09, 1e-12);
  }
  const double other_change = (wider.topLeftCorner<kGnssError, kGnssError>() -
                               before.topLeftCorner<kGnssError, kGnssError>())
                                  .cwiseAbs()
                                  .maxCoeff();
  const double cross_change =
      (wider.block<kGnssError, 3>(0, kGnssError) - before.block<kGnssError, 3>(0, kGnssError))
          .cwiseAbs()
          .maxCoeff();
  EXPECT_LT(other_change, 1e-15);
  EXPECT_LT(cross_change, 1e-15);
  // WHEN it fixes again (the float error is gone): the state restarts at zero, uncorrelated, at the
  // new σ
  ekf_.SetGnssErrorModel(30.0, 0.01, true);
  const EkfMatrix fixed = ekf_.covariance();
  EXPECT_EQ(ekf_.gnss_error(), Eigen::Vector3d::Zero());
  const double cross_fixed = fixed.block<kGnssError, 3>(0, kGnssError).cwiseAbs().maxCoeff();
  EXPECT_EQ(cross_fixed, 0.0);
  EXPECT_NEAR(fixed(kGnssError, kGnssError), 1e-4, 1e-15);
  // AND the process uses the new model: the variance stays at the stationary σ² of the new process
  for (int k = 0; k < 100; ++k)
    ekf_.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 9.81) * 0.01, 0.01);
  EXPECT_NEAR(ekf_.covariance()(kGnssError, kGnssError), 1e-4, 1e-9);
  // AND an unchanged model is a no-op
  const EkfMatrix same = ekf_.covariance();
  ekf_.SetGnssErrorModel(30.0, 0.01, true);
  EXPECT_EQ(ekf_.covariance(), same);
}

// issue 39: the height's correlated error scales with the VDOP, the horizontal axes' with the
// HDOP: a rescaled process scales each axis's state and covariance rows by its own ratio.
TEST_F(ErrorStateEkfTest, GnssErrorScaleChangeRescalesTheUpAxisByItsOwnRatio) {
  const Eigen::Vector3d p = Pos(ekf_);
  ASSERT_TRUE(
      ekf_.UpdatePosition(p + Eigen::Vector3d(0.05, -0.02, 0.03), Eigen::Vector3d::Constant(0.05))
          .accepted);
  const EkfMatrix before = ekf_.covariance();
  const Eigen::Vector3d e_before = ekf_.gnss_error();
  const double sigma = ekf_.params().gnss_error_std_m;
  const double up =
      ekf_.params().gnss_error_vertical_std_m > 0 ? ekf_.params().gnss_error_vertical_std_m : sigma;
  // WHEN the HDOP stays and the VDOP triples
  ekf_.SetGnssErrorModel(ekf_.params().gnss_error_tau_s, sigma, 3.0 * up, false);
  const EkfMatrix after = ekf_.covariance();
  // THEN only the up axis scales: its estimate ×3, its variance ×9, its cross-covariances ×3
  EXPECT_NEAR(ekf_.gnss_error().z(), 3.0 * e_before.z(), 1e-15);
  EXPECT_EQ(ekf_.gnss_error().head<2>(), e_before.head<2>());
  const int u = kGnssError + 2;
  EXPECT_NEAR(after(u, u), 9.0 * before(u, u), 1e-15);
  for (int i = 0; i < kNumStates; ++i) {
    if (i == u) continue;
    EXPECT_NEAR(after(i, u), 3.0 * before(i, u), 1e-15) << i;
  }
  EXPECT_TRUE((after.topLeftCorner<u, u>() == before.topLeftCorner<u, u>()));
}

TEST_F(ErrorStateEkfTest, GnssErrorScaleChangeRescalesTheSameProcess) {
  // GIVEN a filter whose correlated GNSS error has an estimate and cross-covariances
  const Eigen::Vector3d p = Pos(ekf_);
  ASSERT_TRUE(
      ekf_.UpdatePosition(p + Eigen::Vector3d(0.05, -0.02, 0.0), Eigen::Vector3d::Constant(0.05))
          .accepted);
  const EkfMatrix before = ekf_.covariance();
  const Eigen::Vector3d e_before = ekf_.gnss_error();
  ASSERT_GT(e_before.norm(), 1e-4);
  const double sigma = ekf_.params().gnss_error_std_m;
  // WHEN the receiver's HDOP doubles (same error process, twice the scale)
  ekf_.SetGnssErrorModel(ekf_.params().gnss_error_tau_s, 2.0 * sigma, false);
  const EkfMatrix after = ekf_.covariance();
  // THEN the estimate doubles, its variance quadruples, its cross-covariances double, the rest
  // stays
  EXPECT_TRUE(ekf_.gnss_error().isApprox(2.0 * e_before, 1e-12));
  const Eigen::Matrix3d var_before = before.block<3, 3>(kGnssError, kGnssError);
  const Eigen::Matrix3d var_after = after.block<3, 3>(kGnssError, kGnssError);
  EXPECT_TRUE(var_after.isApprox(4.0 * var_before, 1e-12));
  const Eigen::Matrix<double, kGnssError, 3> cross_before =
      before.block<kGnssError, 3>(0, kGnssError);
  const Eigen::Matrix<double, kGnssError, 3> cross_after =
      after.block<kGnssError, 3>(0, kGnssError);
  EXPECT_TRUE(cross_after.isApprox(2.0 * cross_before, 1e-12));
  const Eigen::Matrix<double, kGnssError, kGnssError> rest_before =
      before.topLeftCorner<kGnssError, kGnssError>();
  const Eigen::Matrix<double, kGnssError, kGnssError> rest_after =
      after.topLeftCorner<kGnssError, kGnssError>();
  EXPECT_EQ(rest_after, rest_before);
  // AND the process noise follows the new scale: the variance settles at (2σ)² per horizontal axis
  for (int k = 0; k < 20000; ++k)
    ekf_.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 9.81) * 0.01, 0.01);
  EXPECT_NEAR(ekf_.covariance()(kGnssError, kGnssError), 4.0 * sigma * sigma,
              0.01 * 4.0 * sigma * sigma);
}

// issue 39: a reset onto a fix (the IMU back from a loss, or a long rejection) takes the fix's
// correlated error along: the position must not claim the fix's white σ alone.
TEST_F(ErrorStateEkfTest, ResetOntoAFixCarriesTheReceiversCorrelatedError) {
  // GIVEN a filter with correlated GNSS error states (σ 0.3 m per axis)
  const double gm_var = ekf_.covariance()(kGnssError, kGnssError);
  ASSERT_GT(gm_var, 0.0);
  // WHEN it is reset onto a fix whose white σ is 5 cm horizontally and 12 cm up
  const Eigen::Vector3d fix_std(0.05, 0.05, 0.12);
  ekf_.ResetPositionVelocity(Eigen::Vector3d(3, 4, 5), Eigen::Vector3d(1, 0, 0), fix_std, 0.5);
  const EkfMatrix& P = ekf_.covariance();
  for (int i = 0; i < 3; ++i) {
    const double var_e = P(kGnssError + i, kGnssError + i);
    // THEN the position's variance is the white part plus the correlated error's
    EXPECT_NEAR(P(kPos + i, kPos + i), fix_std[i] * fix_std[i] + var_e, 1e-12) << i;
    // AND what the fix measured (position + correlated error) is known to its white σ alone
    const double measured_var = P(kPos + i, kPos + i) + var_e + 2.0 * P(kPos + i, kGnssError + i);
    EXPECT_NEAR(measured_var, fix_std[i] * fix_std[i], 1e-12) << i;
  }
  // AND the antenna is where the fix put it, its correlated error restarted at zero
  EXPECT_TRUE(Pos(ekf_).isApprox(Eigen::Vector3d(3, 4, 5), 1e-12));
}

TEST(ErrorStateEkfGnssModelTest, SwitchIsIgnoredWithoutCorrelatedStates) {
  ErrorStateEkf ekf(EkfParams{}, EarthModel{});  // gnss_error_tau_s = 0: plain 15-state filter
  ekf.Initialize(NavState{});
  const EkfMatrix before = ekf.covariance();
  ekf.SetGnssErrorModel(2.0, 0.5, true);
  EXPECT_EQ(ekf.covariance(), before);
}

// Predict symmetrises only the block of δp, δv, φ, and the updates compute the Joseph form's lower
// triangle alone: both take P as exactly symmetric on entry. Every operation keeps it so, bit for
// bit, with every state on and the turn states learnable (at speed, turning, a lateral force).
TEST_F(ErrorStateEkfTest, CovarianceStaysExactlySymmetric) {
  EkfParams p = ekf_.params();
  p.speed_dev_tau_s = 3.0;     // the speed deviation's decay
  p.mount_yaw_std_rad = 0.02;  // both mounting angles
  ErrorStateEkf e(p, EarthModel{});
  e.Initialize(ekf_.state());
  const auto symmetric = [&e] { return e.covariance() == e.covariance().transpose(); };
  const Eigen::Vector3d dth(0.001, -0.0005, 0.004), dv(0.0, 0.03, 0.0981);
  for (int k = 0; k < 400; ++k) {
    e.Predict(dth, dv, 0.01);
    ASSERT_TRUE(symmetric()) << "Predict " << k;
    if (k % 10 != 9) continue;
    e.UpdatePosition(e.AntennaPosition() + Eigen::Vector3d(0.02, -0.01, 0.03),
                     Eigen::Vector3d(0.05, 0.05, 0.1));
    ASSERT_TRUE(symmetric()) << "UpdatePosition " << k;
    e.UpdateVelocity(e.AntennaVelocity() + Eigen::Vector3d(0.01, 0.0, -0.01),
                     Eigen::Vector3d::Constant(0.05));
    e.UpdateNonHolonomic();
    e.UpdateSpeedModel();
    e.UpdateYaw(0.6, 0.05);
    ASSERT_TRUE(symmetric()) << "updates " << k;
    if (k % 100 == 99) {
      e.InflateCovariance(1.5);
      e.SetGnssErrorModel(5.0, 0.3 + 0.001 * k, false);
      ASSERT_TRUE(symmetric()) << "fading, rescaled GNSS error " << k;
    }
  }
  EXPECT_GT(std::abs(e.covariance()(kVel + 1, kAccelScaleY)), 0.0);  // the turn states learned
  EXPECT_GT(std::abs(e.covariance()(kAtt, kGyroCouplingX)), 0.0);
  EXPECT_GT(std::abs(e.covariance()(kGnssError, kSpeedDev)), 0.0);  // the decaying states
  e.ResetSetSpeed(0.1);
  e.ResetPositionVelocity(e.AntennaPosition(), e.state().v_N_mps, Eigen::Vector3d::Constant(0.1),
                          0.1);
  e.RestartTimeBaseStates();
  e.UpdateZeroVelocity(0.05);
  e.Predict(dth, dv, 0.01);
  EXPECT_TRUE(symmetric());
}

// The update takes the Joseph form on P's lower triangle (JosephUpdate, and the dense form for the
// classic and one-row updates): one position fix (three rows), one NHC (two) and one heading (one)
// each give the textbook (I − KH) P (I − KH)ᵀ + K R Kᵀ.
TEST_F(ErrorStateEkfTest, UpdatesEqualTheJosephForm) {
  for (int k = 0; k < 50; ++k) {
    ekf_.Predict(raw_w_ * 0.01, Eigen::Vector3d(0.1, 0.3, 9.81) * 0.01, 0.01);
    if (k % 10 == 9) ekf_.UpdateVelocity(ekf_.AntennaVelocity(), Eigen::Vector3d::Constant(0.05));
  }
  const auto check = [this](auto update, const auto& H, const auto& R) {
    const EkfMatrix P0 = ekf_.covariance();
    ASSERT_TRUE(update().accepted);
    const auto S = (H * P0 * H.transpose() + R).eval();
    const auto K = (P0 * H.transpose() * S.inverse()).eval();
    const EkfMatrix I_KH = EkfMatrix::Identity() - K * H;
    const EkfMatrix expected = I_KH * P0 * I_KH.transpose() + K * R * K.transpose();
    EXPECT_LE((ekf_.covariance() - expected).cwiseAbs().maxCoeff(),
              1e-12 * expected.cwiseAbs().maxCoeff());
  };
  const Eigen::Vector3d pos_std(0.05, 0.05, 0.1);
  const Eigen::Matrix3d R_pos = pos_std.cwiseAbs2().asDiagonal();
  check([&] { return ekf_.UpdatePosition(Pos(ekf_) + Eigen::Vector3d(0.02, -0.01, 0.0), pos_std); },
        ekf_.PositionJacobian(), R_pos);
  const Eigen::Matrix2d R_nhc = Eigen::Matrix2d::Identity() * 0.05 * 0.05;
  check([&] { return ekf_.UpdateNonHolonomic(); }, ekf_.NonHolonomicJacobian(), R_nhc);
  Eigen::Matrix<double, 1, kNumStates> H_yaw = Eigen::Matrix<double, 1, kNumStates>::Zero();
  H_yaw(0, kAtt + 2) = 1.0;
  const Eigen::Matrix<double, 1, 1> R_yaw = Eigen::Matrix<double, 1, 1>::Constant(0.1 * 0.1);
  const Eigen::Vector3d x_N = ekf_.state().q_NB * Eigen::Vector3d::UnitX();
  check([&] { return ekf_.UpdateYaw(std::atan2(x_N.y(), x_N.x()) + 0.01, 0.1); }, H_yaw, R_yaw);
}

// The classic filter (augmented states off) propagates and updates only P's first 15 states:
// its other rows and columns stay exact zeros, and one interval equals the dense Φ P Φᵀ + Q
// written out here from the error dynamics in the header.
// With `gyro_scale_z_std` > 0 the z gyro's scale state, the x and y gyros' couplings to the z rate,
// the residual tag lag and the accelerometer's lateral-force states are on (the full path): Φ
// gains their columns in the attitude rows, −Ĉ[ẑ x̂ ŷ]·ω_z·dt, and in the velocity rows,
// −Ĉ[ŷ x̂ ẑ]·f̄_y·dt, f̄_y the lateral force low-passed (the residual lag has none: a random
// constant seen only by the fixes); so are the x and y gyros' scales, −Ĉ[x̂·ω_x ŷ·ω_y]·dt in
// the attitude rows and their random walk on the diagonal.
void CheckPropagationAgainstTheDenseProduct(double gyro_scale_z_std) {
  EkfParams p;
  p.lever_arm_B_m = Eigen::Vector3d(0.3, 0.1, 0.9);
  p.gyro_scale_std = 0.005;
  p.nhc_std_mps = 0.05;
  p.estimate_mount_angles = false;  // the classic states alone (the mounting states are tails)
  p.gyro_scale_z_std = gyro_scale_z_std;
  p.gyro_z_coupling_x_std_rad = p.gyro_z_coupling_y_std_rad = gyro_scale_z_std > 0 ? 0.005 : 0.0;
  p.accel_y_force_std = gyro_scale_z_std > 0 ? 0.005 : 0.0;
  p.imu_time_residual_std_s = gyro_scale_z_std > 0 ? 0.01 : 0.0;
  p.gyro_scale_xy_std = gyro_scale_z_std > 0 ? 0.005 : 0.0;
  p.gyro_scale_xy_rw_rthz = 1e-4;
  EarthModel earth;
  earth.w_IE_N_radps = Eigen::Vector3d(0.0, 6.3e-5, 3.7e-5);
  ErrorStateEkf ekf(p, earth);
  NavState s;
  s.v_N_mps = Eigen::Vector3d(3.0, 0.6, 0.0);  // above 2 m/s: the fixes teach the residual lag
  s.q_NB = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::Quaterniond::Identity();
  ekf.Initialize(s);
  const Eigen::Vector3d dth(0.001, -0.0005, 0.003), dv(0.02, 0.01, 0.0981);
  for (int k = 0; k < 50; ++k) {  // correlations between every classic state
    ekf.Predict(dth, dv, 0.01);
    if (k % 10 == 9) {
      ekf.UpdatePosition(ekf.AntennaPosition() + Eigen::Vector3d(0.02, -0.01, 0.03),
                         Eigen::Vector3d(0.05, 0.05, 0.1));
      ekf.UpdateNonHolonomic();
    }
  }
  const double dt = 0.01;
  const EkfMatrix P0 = ekf.covariance();
  const Eigen::Matrix3d C = ekf.state().q_NB.toRotationMatrix();
  Eigen::Vector3d dv_used = dv - ekf.accel_bias() * dt;
  dv_used.y() /= 1.0 + ekf.accel_y_force_error().x();
  dv_used.x() -= ekf.accel_y_force_error().y() * dv_used.y();
  dv_used.z() -= ekf.accel_y_force_error().z() * dv_used.y();
  const Eigen::Vector3d f_N = C * dv_used / dt;
  Eigen::Vector3d dth_used = dth - ekf.gyro_bias() * dt;
  dth_used.z() /= 1.0 + ekf.gyro_scale_z();
  dth_used.head<2>() -= ekf.gyro_z_coupling_rad() * dth_used.z();
  dth_used.head<2>().array() /= 1.0 + ekf.gyro_scale_xy().array();
  const double turned_rad = dth_used.norm();
  ekf.Predict(dth, dv, dt);
  EkfMatrix Phi = EkfMatrix::Identity();
  const Eigen::Matrix3d W = Skew(earth.w_IE_N_radps);
  Phi.block<3, 3>(kPos, kVel) = Eigen::Matrix3d::Identity() * dt;
  Phi.block<3, 3>(kVel, kVel) -= 2.0 * W * dt;
  Phi.block<3, 3>(kVel, kAtt) = -Skew(f_N) * dt;
  Phi.block<3, 3>(kVel, kAccelBias) = -C * dt;
  Phi.block<3, 3>(kAtt, kAtt) -= W * dt;
  Phi.block<3, 3>(kAtt, kGyroBias) = -C * dt;
  Phi.block<3, 1>(kAtt, kGyroScaleZ) = -C.col(2) * dth_used.z();
  Phi.block<3, 1>(kAtt, kGyroCouplingX) = -C.col(0) * dth_used.z();
  Phi.block<3, 1>(kAtt, kGyroCouplingY) = -C.col(1) * dth_used.z();
  if (gyro_scale_z_std > 0) {
    Phi.block<3, 1>(kAtt, kGyroScaleX) = -C.col(0) * dth_used.x();
    Phi.block<3, 1>(kAtt, kGyroScaleY) = -C.col(1) * dth_used.y();
  }
  // the lateral force low-passed (kLateralForceSmoothing_s) as the prediction took it
  const double f_y_lp = ekf.lateral_force_lp_B_mps2();
  EXPECT_GT(f_y_lp, 0.5 * dv_used.y() / dt);  // the low-pass has risen towards the 1 m/s² given
  Phi.block<3, 1>(kVel, kAccelScaleY) = -C.col(1) * f_y_lp * dt;
  Phi.block<3, 1>(kVel, kAccelCouplingXY) = -C.col(0) * f_y_lp * dt;
  Phi.block<3, 1>(kVel, kAccelCouplingZY) = -C.col(2) * f_y_lp * dt;
  EkfMatrix Q = EkfMatrix::Zero();
  for (int i = 0; i < 3; ++i) {
    Q(kVel + i, kVel + i) = p.accel_noise_mps2_rthz * p.accel_noise_mps2_rthz * dt;
    Q(kAtt + i, kAtt + i) = p.gyro_noise_radps_rthz * p.gyro_noise_radps_rthz * dt +
                            p.gyro_scale_std * p.gyro_scale_std * std::numbers::pi * turned_rad;
    Q(kAccelBias + i, kAccelBias + i) = p.accel_bias_rw_mps3_rthz * p.accel_bias_rw_mps3_rthz * dt;
    Q(kGyroBias + i, kGyroBias + i) = p.gyro_bias_rw_radps2_rthz * p.gyro_bias_rw_radps2_rthz * dt;
  }
  if (gyro_scale_z_std > 0) {
    Q(kGyroScaleX, kGyroScaleX) = Q(kGyroScaleY, kGyroScaleY) =
        p.gyro_scale_xy_rw_rthz * p.gyro_scale_xy_rw_rthz * dt;
  }
  const EkfMatrix expected = Phi * P0 * Phi.transpose() + Q;
  const EkfMatrix& P = ekf.covariance();
  EXPECT_LE((P - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_GT(std::abs(P(kPos, kGyroBias)), 0.0);  // the test saw real cross-covariances
  if (gyro_scale_z_std > 0) {
    EXPECT_GT(std::abs(P(kAtt + 2, kGyroScaleZ)), 0.0);  // the scale's heading correlation
    EXPECT_GT(std::abs(P(kAtt, kGyroCouplingX)), 0.0);   // the couplings' tilt correlations
    EXPECT_GT(std::abs(P(kAtt + 1, kGyroCouplingY)), 0.0);
    EXPECT_GT(std::abs(P(kPos, kImuTimeResidual)), 0.0);  // the fixes saw the residual lag
    EXPECT_GT(std::abs(P(kVel + 1, kAccelScaleY)), 0.0);  // the lateral force's velocity terms
    EXPECT_GT(std::abs(P(kVel, kAccelCouplingXY)), 0.0);
    EXPECT_GT(std::abs(P(kVel + 2, kAccelCouplingZY)), 0.0);
    EXPECT_GT(std::abs(P(kAtt + 1, kGyroScaleX)), 0.0);  // the x and y scales' tilt correlations
    EXPECT_GT(std::abs(P(kAtt, kGyroScaleY)), 0.0);
    EXPECT_TRUE(P.middleRows<kGyroScaleZ - kNumClassicStates>(kNumClassicStates).isZero(0.0));
    return;
  }
  EXPECT_TRUE(P.bottomRows<kNumStates - kNumClassicStates>().isZero(0.0));
  EXPECT_TRUE(P.rightCols<kNumStates - kNumClassicStates>().isZero(0.0));
}

TEST(ErrorStateEkfClassicTest, PropagationEqualsTheDenseProductAndKeepsTheTailZero) {
  CheckPropagationAgainstTheDenseProduct(0.0);
}

TEST(ErrorStateEkfGyroScaleTest, PropagationEqualsTheDenseProductWithTheZGyroScale) {
  CheckPropagationAgainstTheDenseProduct(0.005);
}

}  // namespace
}  // namespace hil::estimator

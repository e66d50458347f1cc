// The error-state EKF's z-gyro scale factor (ErrorStateEkf, kGyroScaleZ): a car drives straight
// rows with 180° U-turns between them on 10 Hz RTK-class fixes, its z gyro reading 0.5 % high (a
// consumer MEMS's sensitivity tolerance). Each turn then leaves 0.9° of heading error, which the
// filter (with the correlated-GNSS-error state of navd's car configuration) carries into the next
// row as a heading error and a cross-track offset. With the scale estimated, the filter must learn
// it from the turns and the heading error must go.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "hil/estimator/error_state_ekf.h"

namespace hil::estimator {
namespace {

using namespace ekf_index;

constexpr double kDt = 0.01;             // IMU interval (100 Hz)
constexpr double kScaleError = 0.005;    // the z gyro reads 0.5 % high (the brief's example)
constexpr double kRow_s = 40.0;          // a row: 40 s at 5 m/s
constexpr double kTurnRate_radps = 0.3;  // U-turn at 0.3 rad/s: 10.5 s for π
constexpr double kSpeed_mps = 5.0;
const double kPeriod_s = kRow_s + std::numbers::pi / kTurnRate_radps;

// The yaw rate of the car at t: rows, then left U-turns (ENU, counter-clockwise).
double YawRate(double t_s) { return std::fmod(t_s, kPeriod_s) < kRow_s ? 0.0 : kTurnRate_radps; }

// The EKF's gravity at a position (mechanization.cc: plumb line tilting away from the origin).
Eigen::Vector3d Gravity(const Eigen::Vector3d& p) {
  const double g = 9.80665, r = 6371000.0;
  return Eigen::Vector3d(-g * p.x() / r, -g * p.y() / r, -g + 2.0 * g * p.z() / r);
}

class UTurnRun {
 public:
  // `scale_std`: the filter's prior σ of the z gyro's scale error (0: not estimated)
  explicit UTurnRun(double scale_std) {
    EkfParams p;
    p.accel_noise_mps2_rthz = 0.01;
    p.gyro_noise_radps_rthz = 5e-4;
    p.nhc_std_mps = 0.05;
    // the car's correlated RTK error model (field_realism/imu_time_tag_lag.yaml): it holds an
    // offset the turn left for tens of seconds
    p.gnss_error_tau_s = 30.0;
    p.gnss_error_std_m = 0.008;
    p.gyro_scale_z_std = scale_std;
    ekf_ = ErrorStateEkf(p, EarthModel{});
    NavState s;
    s.v_N_mps = VelocityN();
    s.q_NB = Attitude();
    ekf_.Initialize(s);
  }
  // Runs to t_end_s on the fixes (10 Hz, white σ 1 cm, 5 cm/s) and the NHC (10 Hz); adds the
  // cross-track error (to the car's left) and the yaw error (counter-clockwise) of every 100 ms in
  // [after_s, t_end_s) to their means.
  void RunTo(double t_end_s, double after_s) {
    while (t_ + 0.5 * kDt < t_end_s) {
      Step();
      if (++k_ % 10 != 0) continue;
      ekf_.UpdateNonHolonomic();
      const Eigen::Vector3d n_p(n_(rng_), n_(rng_), n_(rng_));
      const Eigen::Vector3d n_v(n_(rng_), n_(rng_), n_(rng_));
      ekf_.UpdatePosition(p_N_m_ + 0.01 * n_p, Eigen::Vector3d::Constant(0.01));
      ekf_.UpdateVelocity(VelocityN() + 0.05 * n_v, Eigen::Vector3d::Constant(0.05));
      if (t_ < after_s) continue;
      const Eigen::Vector3d left_N = Attitude() * Eigen::Vector3d::UnitY();
      cross_sum_m_ += left_N.dot(ekf_.state().p_N_m - p_N_m_);
      const Eigen::AngleAxisd yaw_error(ekf_.state().q_NB * Attitude().inverse());
      yaw_error_sum_rad_ += yaw_error.angle() * yaw_error.axis().z();
      ++cross_n_;
    }
  }
  double MeanCrossTrack_m() const {
    return cross_n_ > 0 ? cross_sum_m_ / static_cast<double>(cross_n_) : 0.0;
  }
  double MeanYawError_deg() const {
    return cross_n_ > 0
               ? yaw_error_sum_rad_ / static_cast<double>(cross_n_) * 180.0 / std::numbers::pi
               : 0.0;
  }
  const ErrorStateEkf& ekf() const { return ekf_; }

 private:
  Eigen::Quaterniond Attitude() const {
    return Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad_, Eigen::Vector3d::UnitZ()));
  }
  Eigen::Vector3d VelocityN() const { return Attitude() * Eigen::Vector3d(kSpeed_mps, 0, 0); }
  // One IMU interval: the increments at the interval's middle, the z gyro's scaled, then the truth
  // advanced.
  void Step() {
    const double w = YawRate(t_ + 0.5 * kDt);
    const Eigen::AngleAxisd C_mid(yaw_rad_ + 0.5 * w * kDt, Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d v_mid = C_mid * Eigen::Vector3d(kSpeed_mps, 0, 0);
    const Eigen::Vector3d a_N = C_mid * Eigen::Vector3d(0, kSpeed_mps * w, 0);
    const Eigen::Vector3d f_B = C_mid.inverse() * (a_N - Gravity(p_N_m_ + 0.5 * kDt * v_mid));
    const Eigen::Vector3d w_B(0, 0, (1.0 + kScaleError) * w);
    const Eigen::Vector3d n_g(n_(rng_), n_(rng_), n_(rng_)), n_a(n_(rng_), n_(rng_), n_(rng_));
    ekf_.Predict(w_B * kDt + 5e-4 * std::sqrt(kDt) * n_g, f_B * kDt + 0.01 * std::sqrt(kDt) * n_a,
                 kDt);
    p_N_m_ += v_mid * kDt;
    yaw_rad_ += w * kDt;
    t_ += kDt;
  }

  ErrorStateEkf ekf_;
  Eigen::Vector3d p_N_m_ = Eigen::Vector3d::Zero();
  double yaw_rad_ = 0.0;
  double t_ = 0.0;
  long k_ = 0;
  double cross_sum_m_ = 0.0;
  double yaw_error_sum_rad_ = 0.0;
  long cross_n_ = 0;
  std::mt19937_64 rng_{2026};
  std::normal_distribution<double> n_{0.0, 1.0};
};

TEST(GyroScaleTest, UTurnsTeachTheZGyroScaleWithinAThousandth) {
  // GIVEN a car whose z gyro reads 0.5 % high, the scale estimated with a 0.5 % prior σ
  UTurnRun run(0.005);
  // WHEN it drives 6 rows and 6 U-turns on the fixes
  run.RunTo(6 * kPeriod_s, 6 * kPeriod_s);
  // THEN the scale is known within 0.1 %, and its σ says so
  EXPECT_NEAR(run.ekf().gyro_scale_z(), kScaleError, 0.001);
  EXPECT_LT(std::sqrt(run.ekf().covariance()(kGyroScaleZ, kGyroScaleZ)), 0.001);
}

TEST(GyroScaleTest, TheTurnsNoLongerLeaveAHeadingError) {
  // GIVEN the same car, with the scale estimated and without (the filter before the state)
  UTurnRun with(0.005), without(0.0);
  // WHEN it drives 3 rows and turns to learn, then 21 more, measured on their rows' first 10 s
  // (where the error a turn leaves is largest). The 10 Hz centimetre fixes hold the offset to
  // millimetres, so its mean needs many rows to rise above the fixes' noise: over 60 seeds the
  // ratio of the means below reached 0.16 for the heading and 0.54 for the cross-track (stop 49's
  // CI failed a bound of 0.2 on the cross-track over 3 rows, where the noise alone reaches it).
  for (int i = 3; i < 24; ++i) {
    const double row_start_s = i * kPeriod_s;
    with.RunTo(row_start_s, 1e9);
    without.RunTo(row_start_s, 1e9);
    with.RunTo(row_start_s + 10.0, row_start_s);
    without.RunTo(row_start_s + 10.0, row_start_s);
  }
  // THEN the mean heading error after a turn is less than a third of the one without the state
  // (0.09°-0.13° without it over those seeds), and the cross-track offset it leaves is smaller
  EXPECT_LT(std::abs(with.MeanYawError_deg()), std::abs(without.MeanYawError_deg()) / 3.0)
      << "with " << with.MeanYawError_deg() << "°, without " << without.MeanYawError_deg() << "°";
  EXPECT_LT(std::abs(with.MeanCrossTrack_m()), 0.75 * std::abs(without.MeanCrossTrack_m()))
      << "with " << with.MeanCrossTrack_m() << " m, without " << without.MeanCrossTrack_m() << " m";
}

}  // namespace
}  // namespace hil::estimator

#include "hil/estimator/error_state_ekf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace hil::estimator {

using namespace ekf_index;

namespace {
bool AllFinite(const Eigen::Vector3d& v) { return v.allFinite(); }
bool SpeedDevState(const EkfParams& p) { return p.speed_rw_mps_rthz > 0 && p.speed_dev_tau_s > 0; }
// The gyro scale estimates' bounds, for a start value and every injection. ±10 % for k̂_z (ours: a
// gyro that far off its data sheet's ±0.5 % is broken, and 1 + k̂_z must stay away from 0); ±20 %
// for k̂_x, k̂_y (ours: 1 + k̂ stays away from 0; KF-GINS's own estimates reach 0.13 on the real car
// drive_0708, where they take up more than a scale error).
constexpr double kGyroScaleZMax = 0.1;
constexpr double kGyroScaleXyMax = 0.2;

// Column c of X·B (X: three columns of P, B: 3 × 3) in the order of Eigen's vectorised
// coefficient-wise product, which the propagation's products took: (x₀b₀c + x₁b₁c) + x₂b₂c.
template <typename Cols>
[[gnu::always_inline]] inline auto ProductColumn(const Cols& X, const Eigen::Matrix3d& B, int c) {
  return (X.col(0) * B(0, c) + X.col(1) * B(1, c)) + X.col(2) * B(2, c);
}

// P Hᵀ over H's non-zero columns alone (a position fix's H has 10 of 30, the NHC's 8), each sum
// k ascending as Eigen's vectorised lazy product sums it: a zero column added exact zeros.
template <int N, int M, typename Block>
Eigen::Matrix<double, N, M> ProductWithTransposed(const Block& P,
                                                  const Eigen::Matrix<double, M, N>& H) {
  Eigen::Matrix<double, N, M> PHt = Eigen::Matrix<double, N, M>::Zero();
  bool first = true;
  for (int k = 0; k < N; ++k) {
    if (H.col(k).isZero(0.0)) continue;
    if (first) {
      PHt = P.col(k) * H.col(k).transpose();
    } else {
      PHt += P.col(k) * H.col(k).transpose();
    }
    first = false;
  }
  return PHt;
}

// The Joseph update P ← P − A − Aᵀ + L, A = K (PHᵀ)ᵀ, L = (KS) Kᵀ, followed by ½ (P + Pᵀ), on
// the lower triangle alone (mirrored), each entry the value of the dense expression and the
// symmetrisation after it: every sum in Eigen's order, and P exactly symmetric on entry (it is:
// ErrorStateEkfTest, CovarianceStaysExactlySymmetric), so that the dense result's entry (j, i) is
// ((P(i, j) − A(j, i)) − A(i, j)) + L(j, i). Column j's rows S … N − 1 (S = j or j − 1), a
// fixed-size segment:
template <int N, int M, int S, typename Block>
Eigen::Matrix<double, N - S, 1> JosephSegment(const Block& P, const Eigen::Matrix<double, N, M>& K,
                                              const Eigen::Matrix<double, N, M>& PHt,
                                              const Eigen::Matrix<double, N, M>& KS, int j) {
  static_assert(M >= 1 && M <= 3, "the measurement updates have one to three rows");
  constexpr int kLen = N - S;
  const auto rows = [](const Eigen::Matrix<double, N, M>& X, int k) {
    return X.col(k).template segment<kLen>(S);
  };
  // A(i, j) and A(j, i) as Eigen's vectorised lazy product sums them, k ascending
  Eigen::Matrix<double, kLen, 1> a = rows(K, 0) * PHt(j, 0);
  Eigen::Matrix<double, kLen, 1> at = rows(PHt, 0) * K(j, 0);
  for (int k = 1; k < M; ++k) {
    a += rows(K, k) * PHt(j, k);
    at += rows(PHt, k) * K(j, k);
  }
  // L(i, j) and L(j, i) as Eigen's scalar reduction of a coefficient sums them (halves:
  // x₀ + (x₁ + x₂) for three terms), which the dense expression's coefficient-wise (KS)Kᵀ took
  Eigen::Matrix<double, kLen, 1> l = rows(KS, 0) * K(j, 0);
  Eigen::Matrix<double, kLen, 1> lt = rows(K, 0) * KS(j, 0);
  if constexpr (M == 2) {
    l += rows(KS, 1) * K(j, 1);
    lt += rows(K, 1) * KS(j, 1);
  } else if constexpr (M == 3) {
    l += rows(KS, 1) * K(j, 1) + rows(KS, 2) * K(j, 2);
    lt += rows(K, 1) * KS(j, 1) + rows(K, 2) * KS(j, 2);
  }
  const auto p = P.col(j).template segment<kLen>(S);
  return 0.5 * ((((p - a) - at) + l) + (((p - at) - a) + lt));
}
// Columns S and S + 1 from row S (even: aligned packets, no scalar tail); the entry (S, S + 1)
// above the diagonal comes out as its mirror (its X and Y are the mirror's Y and X).
template <int N, int M, int S, typename Block>
void JosephColumnPair(Block& P, const Eigen::Matrix<double, N, M>& K,
                      const Eigen::Matrix<double, N, M>& PHt,
                      const Eigen::Matrix<double, N, M>& KS) {
  constexpr int kLen = N - S;
  const Eigen::Matrix<double, kLen, 1> first = JosephSegment<N, M, S>(P, K, PHt, KS, S);
  const Eigen::Matrix<double, kLen, 1> second = JosephSegment<N, M, S>(P, K, PHt, KS, S + 1);
  P.col(S).template segment<kLen>(S) = first;
  P.col(S + 1).template segment<kLen>(S) = second;
  P.row(S).template segment<kLen>(S) = first.transpose();
  P.row(S + 1).template segment<kLen>(S) = second.transpose();
}
template <int N, int M, typename Block, int... Pair>
void JosephUpdate(Block P, const Eigen::Matrix<double, N, M>& K,
                  const Eigen::Matrix<double, N, M>& PHt, const Eigen::Matrix<double, N, M>& KS,
                  std::integer_sequence<int, Pair...>) {
  static_assert(N % 2 == 0, "columns in pairs");
  (JosephColumnPair<N, M, 2 * Pair>(P, K, PHt, KS), ...);
}
}  // namespace

void ErrorStateEkf::Initialize(const NavState& s) {
  state_ = s;
  memory_ = {};
  ba_.setZero();
  bg_.setZero();
  e_gnss_.setZero();
  q_scale_ = 1.0;
  attitude_hold_ = false;
  set_speed_ = (s.q_NB.conjugate() * s.v_N_mps).x();
  speed_dev_ = 0.0;
  mount_rad_.setZero();
  C_VB_.setIdentity();
  gyro_scale_z_ = 0.0;
  gyro_scale_xy_.setZero();
  ripple_.Reset();
  gyro_z_coupling_rad_.setZero();
  time_residual_s_ = 0.0;
  accel_y_force_.setZero();
  f_y_lp_B_mps2_.setZero();
  speed_at_fix_mps_ = 0.0;
  accel_lp_N_mps2_.setZero();
  gm_tau_s_ = params_.gnss_error_tau_s;
  gm_std_m_ = params_.gnss_error_std_m;
  gm_up_ratio_ = params_.gnss_error_vertical_std_m > 0 && params_.gnss_error_std_m > 0
                     ? params_.gnss_error_vertical_std_m / params_.gnss_error_std_m
                     : 1.0;
  gm_up_std_m_ = gm_std_m_ * gm_up_ratio_;
  P_.setZero();
  RestartGapNoise();
  const auto& p = params_;
  P_.block<3, 3>(kPos, kPos).diagonal().setConstant(p.init_pos_std_m * p.init_pos_std_m);
  P_.block<3, 3>(kVel, kVel).diagonal().setConstant(p.init_vel_std_mps * p.init_vel_std_mps);
  P_(kAtt, kAtt) = P_(kAtt + 1, kAtt + 1) = p.init_roll_pitch_std_rad * p.init_roll_pitch_std_rad;
  P_(kAtt + 2, kAtt + 2) = p.init_yaw_std_rad * p.init_yaw_std_rad;
  P_.block<3, 3>(kAccelBias, kAccelBias)
      .diagonal()
      .setConstant(p.init_accel_bias_std_mps2 * p.init_accel_bias_std_mps2);
  P_.block<3, 3>(kGyroBias, kGyroBias)
      .diagonal()
      .setConstant(p.init_gyro_bias_std_radps * p.init_gyro_bias_std_radps);
  if (p.gnss_error_tau_s > 0) {
    P_.block<3, 3>(kGnssError, kGnssError).diagonal() = GnssErrorVariance(gm_std_m_, gm_up_std_m_);
  }
  if (p.speed_rw_mps_rthz > 0) P_(kSpeed, kSpeed) = p.init_vel_std_mps * p.init_vel_std_mps;
  if (SpeedDevState(p)) P_(kSpeedDev, kSpeedDev) = p.speed_dev_std_mps * p.speed_dev_std_mps;
  if (MountStatesOn()) {
    P_(kMountPitch, kMountPitch) = p.mount_pitch_std_rad * p.mount_pitch_std_rad;
    P_(kMountYaw, kMountYaw) = p.mount_yaw_std_rad * p.mount_yaw_std_rad;
  }
  SetTimeBasePriors();
}

bool ErrorStateEkf::TurnStatesLearnable() const {
  return std::min(state_.v_N_mps.head<2>().norm(), speed_at_fix_mps_) >= kTurnStatesMinSpeed_mps;
}

bool ErrorStateEkf::TimeResidualLearnable() const {
  return TimeResidualStateOn() && state_.v_N_mps.head<2>().norm() >= kResidualMinSpeed_mps;
}

void ErrorStateEkf::ShiftImuTags(double shift_s) {
  if (TimeResidualStateOn() && std::isfinite(shift_s)) time_residual_s_ += shift_s;
}

void ErrorStateEkf::RestartTimeBaseStates() {
  gyro_scale_z_ = 0.0;
  gyro_z_coupling_rad_.setZero();
  time_residual_s_ = 0.0;
  accel_y_force_.setZero();
  gyro_scale_xy_.setZero();
  constexpr int kTriad = kGyroScaleY + 1 - kGyroScaleZ;
  P_.middleRows<kTriad>(kGyroScaleZ).setZero();
  P_.middleCols<kTriad>(kGyroScaleZ).setZero();
  SetTimeBasePriors();
}

void ErrorStateEkf::SetTimeBasePriors() {
  const auto& p = params_;
  if (GyroScaleStateOn()) P_(kGyroScaleZ, kGyroScaleZ) = p.gyro_scale_z_std * p.gyro_scale_z_std;
  if (GyroCouplingStatesOn()) {
    // a coupling whose σ is 0 stays at 0 (its row and column of P stay zero)
    P_(kGyroCouplingX, kGyroCouplingX) = p.gyro_z_coupling_x_std_rad * p.gyro_z_coupling_x_std_rad;
    P_(kGyroCouplingY, kGyroCouplingY) = p.gyro_z_coupling_y_std_rad * p.gyro_z_coupling_y_std_rad;
  }
  if (TimeResidualStateOn())
    P_(kImuTimeResidual, kImuTimeResidual) = p.imu_time_residual_std_s * p.imu_time_residual_std_s;
  if (AccelForceStatesOn())
    P_.block<3, 3>(kAccelScaleY, kAccelScaleY)
        .diagonal()
        .setConstant(p.accel_y_force_std * p.accel_y_force_std);
  if (GyroScaleXyStatesOn())
    P_.block<2, 2>(kGyroScaleX, kGyroScaleX)
        .diagonal()
        .setConstant(p.gyro_scale_xy_std * p.gyro_scale_xy_std);
}

void ErrorStateEkf::SetGyroScale(const Eigen::Vector3d& k) {
  if (GyroScaleStateOn()) gyro_scale_z_ = std::clamp(k.z(), -kGyroScaleZMax, kGyroScaleZMax);
  if (GyroScaleXyStatesOn())
    gyro_scale_xy_ = k.head<2>().cwiseMax(-kGyroScaleXyMax).cwiseMin(kGyroScaleXyMax);
}

Eigen::Vector3d ErrorStateEkf::CompensatedAngle(const Eigen::Vector3d& delta_angle_B_rad,
                                                double dt) const {
  // the z gyro reads (1 + k_z) ω_z + b_z: its scale error is divided out with the bias's removal;
  // the x and y gyros read (1 + k_x) ω_x + m_xz ω_z + b_x (y likewise): the coupling of the z
  // rate removed, then the scale divided out
  Eigen::Vector3d dth = delta_angle_B_rad - bg_ * dt;
  dth.z() /= 1.0 + gyro_scale_z_;
  dth.head<2>() -= gyro_z_coupling_rad_ * dth.z();
  if (GyroScaleXyStatesOn()) dth.head<2>().array() /= 1.0 + gyro_scale_xy_.array();
  return dth;
}

Eigen::Vector3d ErrorStateEkf::CompensatedVelocity(const Eigen::Vector3d& delta_velocity_B_mps,
                                                   double dt) const {
  // the y accelerometer reads (1 + k_ay) f_y + b_y, the x and z f_x + m_xy f_y + b_x and likewise
  Eigen::Vector3d dv = delta_velocity_B_mps - ba_ * dt;
  dv.y() /= 1.0 + accel_y_force_.x();
  dv.x() -= accel_y_force_.y() * dv.y();
  dv.z() -= accel_y_force_.z() * dv.y();
  return dv;
}

void ErrorStateEkf::Predict(const Eigen::Vector3d& delta_angle_B_rad,
                            const Eigen::Vector3d& delta_velocity_B_mps, double dt) {
  if (!(dt > 0) || dt > 1.0 || !AllFinite(delta_angle_B_rad) || !AllFinite(delta_velocity_B_mps))
    return;
  const Eigen::Matrix3d C = state_.q_NB.toRotationMatrix();
  // attitude hold: a standing vehicle turns with the Earth only
  const Eigen::Vector3d dth = attitude_hold_
                                  ? Eigen::Vector3d(C.transpose() * earth_.w_IE_N_radps * dt)
                                  : CompensatedAngle(delta_angle_B_rad, dt);
  const Eigen::Vector3d dv = CompensatedVelocity(delta_velocity_B_mps, dt);
  w_B_ = dth / dt;
  // the lateral force the accelerometer's lateral-force states see: low-passed (two stages), so
  // that the ride's vibration, which the NHC sees as velocity ripple, does not teach them
  const double w_f = std::min(1.0, dt / kLateralForceSmoothing_s);
  f_y_lp_B_mps2_.x() += w_f * (dv.y() / dt - f_y_lp_B_mps2_.x());
  f_y_lp_B_mps2_.y() += w_f * (f_y_lp_B_mps2_.x() - f_y_lp_B_mps2_.y());
  f_N_ = C * dv / dt;
  // the acceleration over about a fix interval, for the residual tag lag's velocity term
  const double w_lp = std::min(1.0, dt / kAccelSmoothing_s);
  accel_lp_N_mps2_ += w_lp * (f_N_ + earth_.g_N_mps2 - accel_lp_N_mps2_);
  // the vehicle-frame velocity change for the ripple's low-pass, only when it is on (a rotation
  // each way per IMU epoch otherwise spent for nothing)
  const Eigen::Vector3d v_V_before =
      ripple_.enabled() ? VehicleVelocity() : Eigen::Vector3d::Zero();
  Propagate(earth_, dth, dv, dt, memory_, state_);
  if (ripple_.enabled()) ripple_.Propagate(VehicleVelocity() - v_V_before, dt);

  const auto& p = params_;
  double gm_decay = 1.0;
  Eigen::Vector3d gm_q = Eigen::Vector3d::Zero();
  if (p.gnss_error_tau_s > 0) {
    gm_decay = std::exp(-dt / gm_tau_s_);
    gm_q = GnssErrorVariance(gm_std_m_, gm_up_std_m_) * (1.0 - gm_decay * gm_decay);
  }
  const double dev_decay = SpeedDevState(p) ? std::exp(-dt / p.speed_dev_tau_s) : 1.0;
  PropagateCovariance(C, dt, gm_decay, dev_decay);
  AddImuNoise(P_.topLeftCorner<kNumClassicStates, kNumClassicStates>(), C, dth.norm(), dt, true);
  AccumulateGapNoise(C, dth.norm(), dt);
  if (p.gnss_error_tau_s > 0) P_.block<3, 3>(kGnssError, kGnssError).diagonal() += gm_q;
  if (GyroScaleXyStatesOn())
    P_.block<2, 2>(kGyroScaleX, kGyroScaleX).diagonal().array() +=
        p.gyro_scale_xy_rw_rthz * p.gyro_scale_xy_rw_rthz * dt;
  if (p.speed_rw_mps_rthz > 0) P_(kSpeed, kSpeed) += p.speed_rw_mps_rthz * p.speed_rw_mps_rthz * dt;
  if (SpeedDevState(p))
    P_(kSpeedDev, kSpeedDev) +=
        p.speed_dev_std_mps * p.speed_dev_std_mps * (1.0 - dev_decay * dev_decay);
  e_gnss_ *= gm_decay;
  speed_dev_ *= dev_decay;
  // PropagateCovariance made the off-diagonal blocks exact transposes, and the block of δb_a …
  // stays exactly symmetric (P is on entry, every operation on P keeps it so: ErrorStateEkfTest,
  // CovarianceStaysExactlySymmetric): a decay scales an entry (i, j) and its mirror by the same
  // factors in the same order, the noise goes on the diagonal. Only the block of δp, δv, φ (their
  // products) needs ½ (P + Pᵀ): the same values a full Symmetrize gives.
  SymmetrizeBlock(0, kAccelBias);
  RepairDiagonal();
}

// The IMU's process noise over one interval on the classic block of P (or of the gap noise)
template <typename Block>
void ErrorStateEkf::AddImuNoise(Block P, const Eigen::Matrix3d& C, double turned_rad, double dt,
                                bool bias_walks) const {
  const auto& p = params_;
  // process noise: the accelerometer's density per body axis, rotated into N
  const double q_accel =
      q_scale_ * accel_scale_ * p.accel_noise_mps2_rthz * p.accel_noise_mps2_rthz;
  const Eigen::Vector3d q_accel_B = accel_noise_floor_B_m2ps3_.cwiseMax(q_accel);
  P.template block<3, 3>(kVel, kVel) += C * q_accel_B.asDiagonal() * C.transpose() * dt;
  if (!attitude_hold_) {
    // the white angle random walk, plus the scale and misalignment error of the angle turned
    // (isotropic: invariant under C)
    P.template block<3, 3>(kAtt, kAtt).diagonal().array() +=
        q_scale_ * accel_scale_ * p.gyro_noise_radps_rthz * p.gyro_noise_radps_rthz * dt +
        p.gyro_scale_std * p.gyro_scale_std * std::numbers::pi * turned_rad;
  }
  if (!bias_walks) return;
  P.template block<3, 3>(kAccelBias, kAccelBias).diagonal().array() +=
      accel_scale_ * p.accel_bias_rw_mps3_rthz * p.accel_bias_rw_mps3_rthz * dt;
  P.template block<3, 3>(kGyroBias, kGyroBias).diagonal().array() +=
      p.gyro_bias_rw_radps2_rthz * p.gyro_bias_rw_radps2_rthz * dt;
}

void ErrorStateEkf::PropagateCovariance(const Eigen::Matrix3d& C, double dt, double gm_decay,
                                        double dev_decay) {
  const PhiBlocks phi = TransposedPhiBlocks(C, dt);
  if (AugmentedStatesOn()) {
    PropagateCovarianceOf<kNumStates>(P_.topLeftCorner<kNumStates, kNumStates>(), phi, dt, gm_decay,
                                      dev_decay);
  } else {
    PropagateCovarianceOf<kNumClassicStates>(
        P_.topLeftCorner<kNumClassicStates, kNumClassicStates>(), phi, dt, gm_decay, dev_decay);
  }
  // the noise of a gap: the augmented states take none (random constants) or none that Φ carries
  // into the classic rows, so their columns of it stay zero
  if (gap_noise_on_)
    PropagateCovarianceOf<kNumClassicStates>(
        gap_noise_.topLeftCorner<kNumClassicStates, kNumClassicStates>(), phi, dt, 1.0, 1.0);
}

void ErrorStateEkf::AccumulateGapNoise(const Eigen::Matrix3d& C, double turned_rad, double dt) {
  // the gap's noise: the white noise only, the part a sensor outside its model (vibration, a
  // walker's gait) exceeds; the biases' random walks are the sensor's own, and scaling them
  // would forget what the biases were known to be. Carried (a second propagation) only once no
  // fix has come for gap_noise_after_s_, started with the white noise of that time unpropagated
  // (its coupling into velocity and position over the first seconds left out), so that an
  // epoch between fixes costs nothing more
  since_fix_s_ += dt;
  turned_since_fix_rad_ += turned_rad;
  auto G = gap_noise_.topLeftCorner<kNumClassicStates, kNumClassicStates>();
  if (gap_noise_on_) {
    AddImuNoise(G, C, turned_rad, dt, false);
  } else if (since_fix_s_ >= gap_noise_after_s_) {
    G.setZero();
    AddImuNoise(G, C, turned_since_fix_rad_, since_fix_s_, false);
    gap_noise_on_ = true;
  }
}

void ErrorStateEkf::RestartGapNoise() {
  gap_noise_on_ = false;
  since_fix_s_ = turned_since_fix_rad_ = 0.0;
  gap_noise_.setZero();
}

// P ← Φ P Φᵀ with Φ = I + F·dt, by its blocks (3 × 3; the last five states are scalars):
//   row δp: [I  I·dt  0  0   0  ]        rows δb_a, δb_g, δs: identity
//   row δv: [0  A     B  −Cdt 0 ]        rows e: gm_decay·I; row δd: dev_decay
//   row φ:  [0  0     D  0   −Cdt]          (and −Ĉ[ẑ x̂ ŷ]ω_z·dt in the columns of δk_z,
//                                                δm_xz, δm_yz; in row δv −Ĉ[ŷ x̂ ẑ]f_y·dt in
//                                                those of δk_ay, δm_xy, δm_zy)
// A = I − 2[ω_IE×]dt, B = −[f_N×]dt, D = I − [ω_IE×]dt. Only the rows of δp, δv, φ need
// products; the rest of P is scaled by Φ's diagonal, and P's symmetry gives the other part.
// P is symmetric, so the products run on its columns (contiguous in Eigen's column-major
// storage; a profile found the strided row blocks' products the costliest part):
// (Φ P)ᵀ's columns = P Φᵀ's, then P' = Φ (P Φᵀ) by rows of that N × 3 block.
// N = 15 when the augmented states are off: their rows and columns of P are exact zeros, which
// Φ keeps, so only the classic block is propagated (the same bits as the whole matrix).
template <int N, typename Block>
void ErrorStateEkf::PropagateCovarianceOf(Block P, const PhiBlocks& phi, double dt, double gm_decay,
                                          double dev_decay) const {
  constexpr int kTail = N - kAccelBias;  // δb_a … (δd)
  using Cols3 = Eigen::Matrix<double, N, 3>;
  const auto cols = [&](int first) { return P.template middleCols<3>(first); };
  // Mᵀ = P Φᵀ, the columns of δp, δv, φ, a column at a time (one pass, no product temporaries)
  const Cols3 Mp = cols(kPos) + dt * cols(kVel);
  Cols3 Mv, Ma;
  for (int c = 0; c < 3; ++c) {
    Mv.col(c) = (ProductColumn(cols(kVel), phi.At, c) + ProductColumn(cols(kAtt), phi.Bt, c)) +
                ProductColumn(cols(kAccelBias), phi.Gt, c);
    Ma.col(c) = ProductColumn(cols(kAtt), phi.Dt, c) + ProductColumn(cols(kGyroBias), phi.Ggt, c);
  }
  const bool learnable = phi.turn.learnable;
  const bool scale_xy = GyroScaleXyStatesOn();
  if constexpr (N == kNumStates) {
    const Eigen::Matrix3d GkT = phi.turn.Gk.transpose(), GaT = phi.turn.Ga.transpose();
    for (int c = 0; c < 3; ++c) {
      if (learnable) {
        Ma.col(c) += ProductColumn(cols(kGyroScaleZ), GkT, c);
        Mv.col(c) += ProductColumn(cols(kAccelScaleY), GaT, c);
        if (scale_xy)
          Ma.col(c) +=
              P.col(kGyroScaleX) * phi.turn.Gs(c, 0) + P.col(kGyroScaleY) * phi.turn.Gs(c, 1);
      } else {
        Ma.col(c) += P.col(kGyroScaleZ) * phi.turn.Gk(c, 0);
      }
    }
  }
  // Φ's diagonal on the tail: P_tail ← Φ_tail P_tail Φ_tailᵀ. Its only entries other than 1 are
  // the decays of e and δd, so only their rows and columns of the tail block are scaled.
  constexpr std::array<int, 4> kDecaying = {kGnssError, kGnssError + 1, kGnssError + 2, kSpeedDev};
  const std::array<double, 4> decay = {gm_decay, gm_decay, gm_decay, dev_decay};
  if constexpr (N == kNumStates) {
    auto T = P.template bottomRightCorner<kTail, kTail>();
    for (int d = 0; d < 4; ++d) {
      T.row(kDecaying[d] - kAccelBias) *= decay[d];
      T.col(kDecaying[d] - kAccelBias) *= decay[d];
    }
  }
  // P' columns of δp, δv, φ = Φ Mᵀ: products in the rows of δp, δv, φ, the tail's rows M's, the
  // decaying ones scaled
  const auto pre = [&](const Cols3& M) {
    Cols3 R;
    R.template middleRows<3>(kPos) =
        M.template middleRows<3>(kPos) + dt * M.template middleRows<3>(kVel);
    R.template middleRows<3>(kVel) = phi.At.transpose() * M.template middleRows<3>(kVel) +
                                     phi.Bt.transpose() * M.template middleRows<3>(kAtt) +
                                     phi.Gt.transpose() * M.template middleRows<3>(kAccelBias);
    R.template middleRows<3>(kAtt) = phi.Dt.transpose() * M.template middleRows<3>(kAtt) +
                                     phi.Ggt.transpose() * M.template middleRows<3>(kGyroBias);
    if constexpr (N == kNumStates) {
      if (learnable) {
        R.template middleRows<3>(kAtt) += phi.turn.Gk * M.template middleRows<3>(kGyroScaleZ);
        R.template middleRows<3>(kVel) += phi.turn.Ga * M.template middleRows<3>(kAccelScaleY);
        if (scale_xy)
          R.template middleRows<3>(kAtt) += phi.turn.Gs * M.template middleRows<2>(kGyroScaleX);
      } else {
        R.template middleRows<3>(kAtt) += phi.turn.Gk.col(0) * M.row(kGyroScaleZ);
      }
    }
    R.template bottomRows<kTail>() = M.template bottomRows<kTail>();
    if constexpr (N == kNumStates) {
      for (int d = 0; d < 4; ++d) R.row(kDecaying[d]) *= decay[d];
    }
    return R;
  };
  P.template middleCols<3>(kPos) = pre(Mp);
  P.template middleCols<3>(kVel) = pre(Mv);
  P.template middleCols<3>(kAtt) = pre(Ma);
  P.template topRightCorner<kAccelBias, kTail>() =
      P.template bottomLeftCorner<kTail, kAccelBias>().transpose();
}

// Φ's columns of the gyro-triad states in the attitude rows (Gk: δk_z, δm_xz, δm_yz) and of the
// accelerometer's lateral-force states in the velocity rows (Ga: δk_ay, δm_xy, δm_zy) for one
// interval:
//   φ̇ = −Ĉ (ẑ δk_z + x̂ δm_xz + ŷ δm_yz) ω_z − Ĉ (x̂ ω_x δk_x + ŷ ω_y δk_y) (Gs; none while the
//   attitude is held),
//   δv̇ = −Ĉ (ŷ δk_ay + x̂ δm_xy + ẑ δm_zy) f̄_y (f̄_y the low-passed lateral force);
// the couplings', the x and y scales' and the lateral-force columns only while the turns teach them
// (ErrorStateEkf::TurnStatesLearnable).
// `learnable` false: only Gk's first column (δk_z) may be non-zero, so the products take it alone
// (the zero columns added exact zeros)
ErrorStateEkf::TurnColumns ErrorStateEkf::TurnStateColumns(const Eigen::Matrix3d& C,
                                                           const Eigen::Vector3d& w_B_radps,
                                                           double f_y_mps2, bool attitude_hold,
                                                           bool learnable, double dt) {
  TurnColumns t;
  if (!attitude_hold) t.Gk << C.col(2), C.col(0), C.col(1);
  t.Gk *= -w_B_radps.z() * dt;
  if (!learnable) {
    t.Gk.rightCols<2>().setZero();
    return t;
  }
  t.learnable = true;
  if (!attitude_hold) {
    t.Gs.col(0) = -C.col(0) * (w_B_radps.x() * dt);
    t.Gs.col(1) = -C.col(1) * (w_B_radps.y() * dt);
  }
  t.Ga << C.col(1), C.col(0), C.col(2);
  t.Ga *= -f_y_mps2 * dt;
  return t;
}

ErrorStateEkf::PhiBlocks ErrorStateEkf::TransposedPhiBlocks(const Eigen::Matrix3d& C,
                                                            double dt) const {
  PhiBlocks b;
  const Eigen::Matrix3d W_dt = Skew(earth_.w_IE_N_radps) * dt;
  b.At = (Eigen::Matrix3d::Identity() - 2.0 * W_dt).transpose();
  b.Bt = (-Skew(f_N_) * dt).transpose();
  // attitude hold: the nominal attitude turns with the Earth as the true one does, so the error
  // stays put (φ̇ = 0: the −[ω_IE×]φ of the gyro-driven attitude is cancelled by the error of the
  // Earth rate resolved in the estimated body frame); rotating it with the Earth over hours
  // moved the unobservable tilt/heading directions and shrank their variance without cause
  b.Dt = attitude_hold_ ? Eigen::Matrix3d::Identity()
                        : Eigen::Matrix3d((Eigen::Matrix3d::Identity() - W_dt).transpose());
  b.Gt = (-C * dt).transpose();
  // attitude hold: the attitude does not integrate the gyro, so its error owes nothing to δb_g
  b.Ggt = attitude_hold_ ? Eigen::Matrix3d::Zero() : b.Gt;
  b.turn = TurnStateColumns(C, w_B_, f_y_lp_B_mps2_.y(), attitude_hold_, TurnStatesLearnable(), dt);
  return b;
}

Eigen::Vector3d ErrorStateEkf::AntennaPosition() const {
  return state_.p_N_m + state_.q_NB * params_.lever_arm_B_m;
}

Eigen::Vector3d ErrorStateEkf::AntennaVelocity() const {
  return state_.v_N_mps + state_.q_NB * w_B_.cross(params_.lever_arm_B_m);
}

Eigen::Matrix<double, 3, kNumStates> ErrorStateEkf::PositionJacobian() const {
  Eigen::Matrix<double, 3, kNumStates> H = Eigen::Matrix<double, 3, kNumStates>::Zero();
  H.block<3, 3>(0, kPos).setIdentity();
  H.block<3, 3>(0, kAtt) = -Skew(state_.q_NB * params_.lever_arm_B_m);
  if (params_.gnss_error_tau_s > 0) H.block<3, 3>(0, kGnssError).setIdentity();
  // the fix sees the INS δt later: its antenna moved on by v·δt
  if (TimeResidualLearnable()) H.col(kImuTimeResidual) = AntennaVelocity();
  return H;
}

Eigen::Matrix<double, 3, kNumStates> ErrorStateEkf::VelocityJacobian() const {
  Eigen::Matrix<double, 3, kNumStates> H = Eigen::Matrix<double, 3, kNumStates>::Zero();
  const Eigen::Matrix3d C = state_.q_NB.toRotationMatrix();
  H.block<3, 3>(0, kVel).setIdentity();
  H.block<3, 3>(0, kAtt) = -Skew(C * w_B_.cross(params_.lever_arm_B_m));
  H.block<3, 3>(0, kGyroBias) = C * Skew(params_.lever_arm_B_m);
  // the scale error turns ω_z as a z-bias of ω_z·δk_z does, the couplings as x and y biases of
  // ω_z·δm_xz and ω_z·δm_yz
  if (GyroScaleStateOn()) H.col(kGyroScaleZ) = H.block<3, 3>(0, kGyroBias).col(2) * w_B_.z();
  if (GyroCouplingStatesOn() && TurnStatesLearnable()) {
    H.col(kGyroCouplingX) = H.block<3, 3>(0, kGyroBias).col(0) * w_B_.z();
    H.col(kGyroCouplingY) = H.block<3, 3>(0, kGyroBias).col(1) * w_B_.z();
  }
  if (GyroScaleXyStatesOn() && TurnStatesLearnable()) {
    H.col(kGyroScaleX) = H.block<3, 3>(0, kGyroBias).col(0) * w_B_.x();
    H.col(kGyroScaleY) = H.block<3, 3>(0, kGyroBias).col(1) * w_B_.y();
  }
  if (TimeResidualLearnable()) H.col(kImuTimeResidual) = accel_lp_N_mps2_;
  return H;
}

Eigen::Vector3d ErrorStateEkf::VehicleVelocity() const {
  return C_VB_ * (state_.q_NB.conjugate() * state_.v_N_mps);
}

Eigen::Matrix<double, 3, kNumStates> ErrorStateEkf::VehicleVelocityJacobian() const {
  // v_V = C_VB Ĉᵀ v with C_VB = Exp(μ)ᵀ: δv and φ enter as in the body frame, rotated by C_VB;
  // a mounting error δμ turns v_V by Exp(δμ)ᵀ ≈ I − [δμ×], so ∂v_V/∂δμ = [v_V×] (its pitch and
  // yaw columns; the roll is not a state)
  const Eigen::Matrix3d CVt = C_VB_ * state_.q_NB.toRotationMatrix().transpose();
  Eigen::Matrix<double, 3, kNumStates> H = Eigen::Matrix<double, 3, kNumStates>::Zero();
  H.block<3, 3>(0, kVel) = CVt;
  H.block<3, 3>(0, kAtt) = CVt * Skew(state_.v_N_mps);
  if (MountStatesOn()) {
    const Eigen::Matrix3d Sv = Skew(VehicleVelocity());
    H.col(kMountPitch) = Sv.col(1);
    H.col(kMountYaw) = Sv.col(2);
  }
  return H;
}

Eigen::Matrix<double, 2, kNumStates> ErrorStateEkf::NonHolonomicJacobian() const {
  return VehicleVelocityJacobian().bottomRows<2>();
}

UpdateResult ErrorStateEkf::UpdatePosition(const Eigen::Vector3d& p_antenna_N_m,
                                           const Eigen::Vector3d& std_m) {
  if (!AllFinite(p_antenna_N_m) || !AllFinite(std_m)) return {};
  const UpdateResult r = Update<3>(p_antenna_N_m - PredictedFixPosition(), PositionJacobian(),
                                   FixPositionNoise(std_m));
  if (r.accepted) {
    speed_at_fix_mps_ = state_.v_N_mps.head<2>().norm();
    RestartGapNoise();
  }
  return r;
}

Eigen::Vector3d ErrorStateEkf::PredictedFixPosition() const {
  return AntennaPosition() + (params_.gnss_error_tau_s > 0 ? e_gnss_ : Eigen::Vector3d::Zero()) +
         AntennaVelocity() * time_residual_s_;
}

Eigen::Matrix3d ErrorStateEkf::FixPositionNoise(const Eigen::Vector3d& std_m) const {
  Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    R(i, i) = std::pow(std::max(std_m[i], params_.gnss_pos_std_floor_m), 2);
  return R;
}

PositionInnovation ErrorStateEkf::PositionInnovationOf(const Eigen::Vector3d& p_antenna_N_m,
                                                       const Eigen::Vector3d& std_m) const {
  PositionInnovation r;
  if (!AllFinite(p_antenna_N_m) || !AllFinite(std_m)) return r;
  const Eigen::Matrix<double, 3, kNumStates> H = PositionJacobian();
  const Eigen::Matrix<double, kNumStates, 3> PHt = P_.lazyProduct(H.transpose());
  r.S_m2 = H * PHt + FixPositionNoise(std_m);
  r.nu_m = p_antenna_N_m - PredictedFixPosition();
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(r.S_m2);
  if (ldlt.info() != Eigen::Success) return r;
  r.nis = r.nu_m.dot(ldlt.solve(r.nu_m));
  r.valid = std::isfinite(r.nis);
  return r;
}

void ErrorStateEkf::ShiftPosition(const Eigen::Vector3d& dp_N_m, const Eigen::Vector3d& var_m2) {
  if (!AllFinite(dp_N_m) || !AllFinite(var_m2)) return;
  state_.p_N_m += dp_N_m;
  P_.block<3, 3>(kPos, kPos).diagonal() += var_m2.cwiseMax(0.0);
}

UpdateResult ErrorStateEkf::UpdateVelocity(const Eigen::Vector3d& v_antenna_N_mps,
                                           const Eigen::Vector3d& std_mps) {
  if (!AllFinite(v_antenna_N_mps) || !AllFinite(std_mps)) return {};
  Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    R(i, i) = std::pow(std::max(std_mps[i], params_.gnss_vel_std_floor_mps), 2);
  const Eigen::Vector3d pred = AntennaVelocity() + accel_lp_N_mps2_ * time_residual_s_;
  return Update<3>(v_antenna_N_mps - pred, VelocityJacobian(), R);
}

UpdateResult ErrorStateEkf::UpdateNonHolonomic() {
  if (!(params_.nhc_std_mps > 0)) return {};
  // the vehicle's lateral and vertical velocity are zero (in V, through the mounting angles)
  const Eigen::Vector3d v_V = VehicleVelocity();
  const Eigen::Vector2d innovation(-v_V.y(), -v_V.z());
  // the IMU's vibration velocity is not the chassis's: its variance is added (VibrationVelocity)
  // (the navigator scales it when the constraint's innovations show the vehicle outside it)
  const double r2 = params_.nhc_std_mps * params_.nhc_std_mps;
  const Eigen::Matrix2d R =
      (nhc_scale_ * Eigen::Vector2d(r2 + vibration_var_B_mps2_.y(), r2 + vibration_var_B_mps2_.z()))
          .asDiagonal();
  return Update<2>(innovation, NonHolonomicJacobian(), R);
}

Eigen::Matrix<double, 1, kNumStates> ErrorStateEkf::SpeedModelJacobian() const {
  // forward vehicle speed x_Vᵀ C_VB Ĉᵀ v minus the set speed; the rest as in the NHC rows
  Eigen::Matrix<double, 1, kNumStates> H = VehicleVelocityJacobian().row(0);
  H(0, kSpeed) = -1.0;
  if (SpeedDevState(params_)) H(0, kSpeedDev) = -1.0;
  return H;
}

UpdateResult ErrorStateEkf::UpdateSpeedModel() {
  if (!(params_.speed_rw_mps_rthz > 0)) return {};
  // the forward speed through the low-pass of vehicle_lowpass_tau_s when on: the ride's ripple is
  // not the chassis's set speed (the NHC keeps the instantaneous velocity: its lateral and vertical
  // rows steer heading and tilt, whose loop a lagged velocity destabilises)
  const double forward = VehicleVelocity().x() - ripple_.ripple_V_mps().x();
  Eigen::Matrix<double, 1, 1> innovation;
  innovation << set_speed_ + speed_dev_ - forward;
  // with a deviation state the pseudo-measurement carries what the state does not: half its σ (a
  // tenth made the attitude terms of H overconfident on the Razor rig: seed000 diverged to metres)
  const double r =
      SpeedDevState(params_) ? 0.5 * params_.speed_dev_std_mps : params_.speed_dev_std_mps;
  Eigen::Matrix<double, 1, 1> R;
  R << r * r + vibration_var_B_mps2_.x();
  return Update<1>(innovation, SpeedModelJacobian(), R);
}

void ErrorStateEkf::ResetSetSpeed(double std_mps) {
  if (!(params_.speed_rw_mps_rthz > 0)) return;
  set_speed_ = VehicleVelocity().x();
  P_.row(kSpeed).setZero();
  P_.col(kSpeed).setZero();
  P_(kSpeed, kSpeed) = std_mps * std_mps;
  if (SpeedDevState(params_)) {
    speed_dev_ = 0.0;
    P_.row(kSpeedDev).setZero();
    P_.col(kSpeedDev).setZero();
    P_(kSpeedDev, kSpeedDev) = params_.speed_dev_std_mps * params_.speed_dev_std_mps;
  }
}

UpdateResult ErrorStateEkf::UpdateYaw(double yaw_enu_rad, double std_rad) {
  if (!std::isfinite(yaw_enu_rad) || !(std_rad > 0)) return {};
  const Eigen::Vector3d x_N = state_.q_NB * Eigen::Vector3d::UnitX();
  const double yaw = std::atan2(x_N.y(), x_N.x());
  double d = std::remainder(yaw_enu_rad - yaw, 2.0 * M_PI);
  Eigen::Matrix<double, 1, kNumStates> H = Eigen::Matrix<double, 1, kNumStates>::Zero();
  // small rotation φ about N changes the yaw by φ_z (level approximation, exact for level attitude)
  H(0, kAtt + 2) = 1.0;
  Eigen::Matrix<double, 1, 1> innovation;
  innovation << d;
  Eigen::Matrix<double, 1, 1> R;
  R << std_rad * std_rad;
  return Update<1>(innovation, H, R);
}

template <int M>
UpdateResult ErrorStateEkf::Update(const Eigen::Matrix<double, M, 1>& innovation,
                                   const Eigen::Matrix<double, M, kNumStates>& H,
                                   const Eigen::Matrix<double, M, M>& R) {
  // with the augmented states off their rows and columns of P are zero, so are their gains
  if (AugmentedStatesOn()) return UpdateOf<kNumStates, M>(innovation, H, R);
  return UpdateOf<kNumClassicStates, M>(innovation, H.template leftCols<kNumClassicStates>(), R);
}

template <int N, int M>
UpdateResult ErrorStateEkf::UpdateOf(const Eigen::Matrix<double, M, 1>& innovation,
                                     const Eigen::Matrix<double, M, N>& H,
                                     const Eigen::Matrix<double, M, M>& R) {
  UpdateResult r;
  r.dof = M;
  auto P = P_.template topLeftCorner<N, N>();
  // lazyProduct: coefficient by coefficient; Eigen's blocked GEMM, which it picks for these
  // sizes, cost 14 k instructions per update in its set-up (callgrind)
  const Eigen::Matrix<double, N, M> PHt = ProductWithTransposed(P, H);
  const Eigen::Matrix<double, M, M> S = H * PHt + R;
  const Eigen::LDLT<Eigen::Matrix<double, M, M>> ldlt(S);
  if (ldlt.info() != Eigen::Success || !innovation.allFinite()) return r;
  r.nis = innovation.dot(ldlt.solve(innovation));
  const double tr_hph = (S - R).trace();
  r.excess = tr_hph > 0 ? std::max(0.0, (innovation.squaredNorm() - R.trace()) / tr_hph) : 0.0;
  if (!WithinGate(r.nis, M, gate_scale_)) return r;
  const Eigen::Matrix<double, M, M> S_inv = ldlt.solve(Eigen::Matrix<double, M, M>::Identity());
  const Eigen::Matrix<double, N, M> K = PHt * S_inv;
  EkfVector dx = EkfVector::Zero();
  dx.template head<N>() = K * innovation;
  // Joseph form (I − KH) P (I − KH)ᵀ + K R Kᵀ keeps P symmetric positive semi-definite. Expanded
  // it is P − K(HP) − (PHᵀ)Kᵀ + K S Kᵀ for any K (S = HPHᵀ + R), taken through the rank-M factors
  // with HP = (PHᵀ)ᵀ (P is symmetric): two N × N × M products where the factored form
  // X = (I − KH)P, X − (XHᵀ)Kᵀ + (KR)Kᵀ took four (a quarter of navd's time per IMU epoch on
  // seed 004 with 23 states went to them); on the lower triangle, mirrored (JosephUpdate)
  const Eigen::Matrix<double, N, M> KS = K * S;
  if constexpr (N == kNumStates && M > 1) {
    JosephUpdate<N, M>(P, K, PHt, KS, std::make_integer_sequence<int, N / 2>{});
  } else {
    // the rarer updates (the classic filter's, the one-row ones) in the dense form, which
    // JosephUpdate's fixed-size columns reproduce: fewer instantiations of them, whose code cost
    // the prediction's products their inlining (callgrind: +0.47 G instructions on seed 004)
    const Eigen::Matrix<double, N, N> KHP = K.lazyProduct(PHt.transpose());
    P = P - KHP - KHP.transpose() + KS.lazyProduct(K.transpose());
    SymmetrizeBlock(0, N);
  }
  RepairDiagonal();
  InjectError(dx);
  r.accepted = true;
  return r;
}

void ErrorStateEkf::InjectError(const EkfVector& dx) {
  state_.p_N_m += dx.segment<3>(kPos);
  state_.v_N_mps += dx.segment<3>(kVel);
  state_.q_NB = (QuatFromRotationVector(dx.segment<3>(kAtt)) * state_.q_NB).normalized();
  ba_ += dx.segment<3>(kAccelBias);
  bg_ += dx.segment<3>(kGyroBias);
  if (params_.gnss_error_tau_s > 0) e_gnss_ += dx.segment<3>(kGnssError);
  if (params_.speed_rw_mps_rthz > 0) set_speed_ += dx[kSpeed];
  if (SpeedDevState(params_)) speed_dev_ += dx[kSpeedDev];
  if (MountStatesOn()) {
    // additive on the two angles (first order: the update's H is [v_V×] at the current μ)
    mount_rad_.y() += dx[kMountPitch];
    mount_rad_.z() += dx[kMountYaw];
    C_VB_ = QuatFromRotationVector(mount_rad_).toRotationMatrix().transpose();
  }
  if (GyroScaleStateOn())
    gyro_scale_z_ = std::clamp(gyro_scale_z_ + dx[kGyroScaleZ], -kGyroScaleZMax, kGyroScaleZMax);
  // clamped to ±0.1 s (ours: ImuTimeOffset's found lag has σ below 10 ms)
  if (TimeResidualStateOn())
    time_residual_s_ = std::clamp(time_residual_s_ + dx[kImuTimeResidual], -0.1, 0.1);
  // clamped to ±0.1 rad (ours: 5.7°, a triad that far from orthogonal is broken, nineteen times
  // the data sheets' σ)
  if (GyroCouplingStatesOn()) {
    gyro_z_coupling_rad_ =
        (gyro_z_coupling_rad_ + dx.segment<2>(kGyroCouplingX)).cwiseMax(-0.1).cwiseMin(0.1);
  }
  // clamped to ±0.1 (ours: 10 % of scale or 5.7° of misalignment, twenty times the data sheets')
  if (AccelForceStatesOn())
    accel_y_force_ = (accel_y_force_ + dx.segment<3>(kAccelScaleY)).cwiseMax(-0.1).cwiseMin(0.1);
  if (GyroScaleXyStatesOn()) {
    gyro_scale_xy_ = (gyro_scale_xy_ + dx.segment<2>(kGyroScaleX))
                         .cwiseMax(-kGyroScaleXyMax)
                         .cwiseMin(kGyroScaleXyMax);
  }
}

Eigen::Vector3d ErrorStateEkf::GnssErrorVariance(double horizontal_std_m, double up_std_m) {
  return Eigen::Vector3d(horizontal_std_m * horizontal_std_m, horizontal_std_m * horizontal_std_m,
                         up_std_m * up_std_m);
}

void ErrorStateEkf::SetGnssErrorModel(double tau_s, double std_m, bool new_source) {
  SetGnssErrorModel(tau_s, std_m, std_m * gm_up_ratio_, new_source);
}

void ErrorStateEkf::SetGnssErrorModel(double tau_s, double std_m, double up_std_m,
                                      bool new_source) {
  if (!(params_.gnss_error_tau_s > 0) || !(tau_s > 0) || !(std_m > 0) || !(up_std_m > 0) ||
      !std::isfinite(tau_s) || !std::isfinite(std_m) || !std::isfinite(up_std_m))
    return;
  if (tau_s == gm_tau_s_ && std_m == gm_std_m_ && up_std_m == gm_up_std_m_) return;
  const Eigen::Vector3d var_old = GnssErrorVariance(gm_std_m_, gm_up_std_m_);
  const Eigen::Vector3d var_new = GnssErrorVariance(std_m, up_std_m);
  if (!new_source && gm_std_m_ > 0 && gm_up_std_m_ > 0) {
    // the same process at another scale per axis: e' = diag(r)·e, so P's rows and columns of e
    // scale by r (the horizontal axes by the HDOP's ratio, the up axis by the VDOP's)
    const Eigen::Vector3d r(std_m / gm_std_m_, std_m / gm_std_m_, up_std_m / gm_up_std_m_);
    e_gnss_ = e_gnss_.cwiseProduct(r);
    for (int i = 0; i < 3; ++i) {
      P_.row(kGnssError + i) *= r[i];
      P_.col(kGnssError + i) *= r[i];
    }
  } else if (std_m > gm_std_m_) {
    // a new error source appears on top of the old one
    P_.block<3, 3>(kGnssError, kGnssError).diagonal() += (var_new - var_old).cwiseMax(0.0);
  } else {
    // the old error is gone: the state restarts, independent of everything else
    e_gnss_.setZero();
    P_.block<3, kNumStates>(kGnssError, 0).setZero();
    P_.block<kNumStates, 3>(0, kGnssError).setZero();
    P_.block<3, 3>(kGnssError, kGnssError).diagonal() = var_new;
  }
  gm_tau_s_ = tau_s;
  gm_std_m_ = std_m;
  gm_up_std_m_ = up_std_m;
}

UpdateResult ErrorStateEkf::UpdateZeroVelocity(double std_mps) {
  if (!(std_mps > 0)) return {};
  Eigen::Matrix<double, 3, kNumStates> H = Eigen::Matrix<double, 3, kNumStates>::Zero();
  H.block<3, 3>(0, kVel).setIdentity();
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * std_mps * std_mps;
  return Update<3>(-state_.v_N_mps, H, R);
}

UpdateResult ErrorStateEkf::UpdateZeroAngularRate(const Eigen::Vector3d& mean_raw_rate_B_radps,
                                                  double std_radps) {
  if (!AllFinite(mean_raw_rate_B_radps) || !(std_radps > 0)) return {};
  // raw rate = b_g + Cᵀ ω_IE (+ noise) for a standing body; the attitude's part of Cᵀ ω_IE is
  // below 1e-7 rad/s per mrad and left out of H
  const Eigen::Vector3d w_IE_B = state_.q_NB.conjugate() * earth_.w_IE_N_radps;
  Eigen::Matrix<double, 3, kNumStates> H = Eigen::Matrix<double, 3, kNumStates>::Zero();
  H.block<3, 3>(0, kGyroBias).setIdentity();
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * std_radps * std_radps;
  return Update<3>(mean_raw_rate_B_radps - w_IE_B - bg_, H, R);
}

void ErrorStateEkf::InflateCovariance(double factor) {
  if (!(factor > 1.0) || !std::isfinite(factor)) return;
  P_.topLeftCorner<kNumClassicStates, kNumClassicStates>() *= factor;
  if (AugmentedStatesOn()) {
    const double s = std::sqrt(factor);
    P_.topRightCorner<kNumClassicStates, kNumStates - kNumClassicStates>() *= s;
    P_.bottomLeftCorner<kNumStates - kNumClassicStates, kNumClassicStates>() *= s;
  }
  ClampFadedVariances();
}

bool ErrorStateEkf::FadeGapNoiseTo(const Eigen::Vector3d& p_antenna_N_m,
                                   const Eigen::Vector3d& std_m, double max_factor) {
  const PositionInnovation in = PositionInnovationOf(p_antenna_N_m, std_m);
  if (!in.valid) return false;
  const Eigen::Matrix<double, 3, kNumClassicStates> H =
      PositionJacobian().leftCols<kNumClassicStates>();
  const Eigen::Matrix<double, kNumClassicStates, kNumClassicStates> G =
      0.5 * (gap_noise_ + gap_noise_.transpose());
  const double tr_hgh = (H * G * H.transpose()).trace();
  const double tr_hph = (in.S_m2 - FixPositionNoise(std_m)).trace();
  // the innovation's variance the covariance lacks, νᵀν − tr S: what λ P would add, (λ − 1) tr HPHᵀ
  const double missing =
      std::min(in.nu_m.squaredNorm() - in.S_m2.trace(), (max_factor - 1.0) * tr_hph);
  if (!gap_noise_on_ || !(tr_hgh > 0) || !(missing > 0) || !std::isfinite(missing)) return false;
  const double g = missing / tr_hgh;
  P_.topLeftCorner<kNumClassicStates, kNumClassicStates>() += g * G;
  gap_noise_ = (1.0 + g) * G;
  ClampFadedVariances();
  return true;
}

void ErrorStateEkf::ClampFadedVariances() {
  // a bias, or the attitude, is never less known than before its first measurement: a variance
  // above its initial one is scaled back to it, with its row and column (P <- D P D, D diagonal).
  // The attitude's too: a fading by a factor of hundreds made an attitude σ of 2° one of 120°,
  // past every small-angle model, and the filter diverged (the real car drive_0708, 15 s outages)
  const auto& p = params_;
  for (int i = kAtt; i < kGyroBias + 3; ++i) {
    const double init_std = i < kAtt + 2     ? p.init_roll_pitch_std_rad
                            : i < kAccelBias ? p.init_yaw_std_rad
                            : i < kGyroBias  ? p.init_accel_bias_std_mps2
                                             : p.init_gyro_bias_std_radps;
    const double var_max = init_std * init_std;
    if (!(P_(i, i) > var_max) || !(var_max > 0)) continue;
    const double c = std::sqrt(var_max / P_(i, i));
    P_.row(i) *= c;
    P_.col(i) *= c;
  }
}

void ErrorStateEkf::SetBiases(const Eigen::Vector3d& accel_bias_B_mps2,
                              const Eigen::Vector3d& gyro_bias_B_radps) {
  if (AllFinite(accel_bias_B_mps2)) ba_ = accel_bias_B_mps2;
  if (AllFinite(gyro_bias_B_radps)) bg_ = gyro_bias_B_radps;
}

void ErrorStateEkf::ResetPositionVelocity(const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                                          const Eigen::Vector3d& pos_std_N_m, double vel_std) {
  state_.p_N_m = p - state_.q_NB * params_.lever_arm_B_m;
  state_.v_N_mps = v;
  e_gnss_.setZero();
  RestartGapNoise();
  P_.block<6, kNumStates>(kPos, 0).setZero();
  P_.block<kNumStates, 6>(0, kPos).setZero();
  P_.block<3, 3>(kPos, kPos).diagonal() = pos_std_N_m.cwiseAbs2();
  P_.block<3, 3>(kVel, kVel).diagonal().setConstant(vel_std * vel_std);
  if (params_.gnss_error_tau_s > 0) {
    // The fix the position is set to holds the receiver's correlated error e as well, which the
    // state restarts at zero: the position's error is then -(e + the fix's white error), so its
    // variance is both, and its covariance with the state's error is -Var(e). Only their sum, what
    // the fix measured, is known to the fix's white σ (a reset onto a NEO-5M fix with σ 0.1 m
    // left a vertical error of 1 m at σ 0.1 m: vertical NEES 7.4 after two MCU resets).
    const Eigen::Vector3d var_e = GnssErrorModelVariance();
    P_.block<3, kNumStates>(kGnssError, 0).setZero();
    P_.block<kNumStates, 3>(0, kGnssError).setZero();
    P_.block<3, 3>(kGnssError, kGnssError).diagonal() = var_e;
    P_.block<3, 3>(kPos, kPos).diagonal() += var_e;
    P_.block<3, 3>(kPos, kGnssError).diagonal() = -var_e;
    P_.block<3, 3>(kGnssError, kPos).diagonal() = -var_e;
  }
}

void ErrorStateEkf::Symmetrize() {
  SymmetrizeBlock(0, kNumStates);
  RepairDiagonal();
}

void ErrorStateEkf::SymmetrizeBlock(int first, int end) {
  // P ← ½ (P + Pᵀ) on the block [first, end)², in place over its pairs below the diagonal
  for (int j = first; j < end; ++j) {
    for (int i = j + 1; i < end; ++i) {
      const double m = 0.5 * (P_(i, j) + P_(j, i));
      P_(i, j) = m;
      P_(j, i) = m;
    }
  }
}

void ErrorStateEkf::RepairDiagonal() {
  // one vectorised test of the whole diagonal first (0 ≤ d < ∞ fails for NaN too)
  const auto d = P_.diagonal().array();
  if ((d >= 0.0).all() && (d < std::numeric_limits<double>::infinity()).all()) return;
  for (int i = 0; i < kNumStates; ++i) {
    if (!(P_(i, i) >= 0) || !std::isfinite(P_(i, i))) {
      P_.row(i).setZero();
      P_.col(i).setZero();
      P_(i, i) = 1e-6;
      ++repairs_;
    }
  }
}

}  // namespace hil::estimator

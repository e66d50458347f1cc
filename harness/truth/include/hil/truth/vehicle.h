#pragma once
/// @file
/// Vehicle models of the truth and their parameter sets.
///
/// Horizontal kinematics of the reference point (rear-axle centre for the bicycle models, the
/// wheel-axle centre for differential drive), ψ the yaw of the body x axis counter-clockwise from
/// east, v the horizontal speed, β a lateral slip angle of the velocity:
///   ė = v cos(ψ + β),  ṅ = v sin(ψ + β),  v̇ = (v_cmd − v) / τ_v
/// - bicycle / tractor (front-wheel steered): ψ̇ = v tan δ / L, and the steering angle δ follows
///   its command through a first-order lag τ_δ with a smooth rate limit r:
///     δ̇ = r · tanh((δ_cmd − δ) / (τ_δ r)),   |δ_cmd| ≤ δ_max
/// - diff_drive: ψ̇ = ω, ω̇ = (ω_cmd − ω) / τ_ω; wheel speeds v ∓ ω·track/2 (turns in place).
/// - skid_steer: a skid-steered base (tracks, or four wheels without steering) in the kinematic
///   model of the tracks' instantaneous centres of rotation (ICRs; Martínez et al. 2005,
///   "Approximating kinematics for tracked mobile robots", IJRR 24(10); Mandow et al. 2007,
///   "Experimental kinematics for wheeled skid-steer mobile robots", IROS): ψ̇ = ω as diff_drive,
///   and in the body frame (x forward, y left) the ICRs of the left and right tracks and of the
///   body lie at (x_v, y_l), (x_v, y_r) and (x_v, v/ω). The tracks' ground speeds are
///   v_l = v − ω·y_l, v_r = v − ω·y_r, so ω = (v_r − v_l) / (y_l − y_r), and the reference point
///   slips sideways at v_y = −x_v·ω. Here the ICRs are symmetric (y_l = −y_r = χ·track/2, a
///   choice): χ ≥ 1 (`icr_expansion`) is how much wider the tracks act in a turn than they are (χ
///   = 1: a differential drive), the turning radius for given track speeds is χ times the one
///   track/2 · (v_r + v_l) / (v_r − v_l) a differential drive would take, and x_v
///   (`icr_offset_m`) is the ICRs' distance ahead of the reference point.
/// Slip (optional): β = −k_slip · v · ψ̇, the velocity swinging to the outside of a turn in
/// proportion to the lateral acceleration.

#include <cstdint>
#include <vector>

namespace hil::truth {

/// Parameters of a vehicle model; constant for a run.
struct VehicleParams {
  enum class Model { kBicycle, kDiffDrive, kSkidSteer };
  Model model = Model::kBicycle;
  double wheelbase_m = 0.84;          ///< bicycle: axle distance L
  double track_m = 0.55;              ///< distance between left and right wheels
  double max_steer_deg = 32;          ///< bicycle: |δ| limit
  double max_steer_rate_dps = 30;     ///< bicycle: steering rate limit r
  double steer_lag_s = 0.2;           ///< bicycle: steering lag τ_δ
  double speed_lag_s = 0.5;           ///< speed lag τ_v (both models)
  double yaw_rate_lag_s = 0.2;        ///< diff_drive, skid_steer: yaw-rate lag τ_ω
  double max_yaw_rate_dps = 45;       ///< diff_drive, skid_steer: |ω_cmd| limit
  double icr_expansion = 1.0;         ///< skid_steer: χ = (y_l − y_r) / track
  double icr_offset_m = 0.0;          ///< skid_steer: x_v, the ICRs ahead of the reference point
  double slip_gain_rad_per_mps2 = 0;  ///< lateral slip k_slip (0: no slip)
  /// Speed variation of a real drive (governor droop, wheel slip on soil, load): the commanded
  /// speed is multiplied by 1 + x(t), x a first-order Gauss–Markov process of this standard
  /// deviation (a fraction, 0: an exactly constant speed) and correlation time, drawn on a 0.1 s
  /// grid from `speed_variation_seed` and interpolated linearly (a deterministic function of t).
  double speed_variation_std = 0;
  double speed_variation_tau_s = 5.0;
  std::uint64_t speed_variation_seed = 1;

  /// Seed 003's greenhouse platform: front-wheel steered, wheelbase 0.84 m, track 0.55 m, ±32°.
  static VehicleParams GreenhousePlatform();
  /// A mid-size tractor for seed 004 (Dongfanghong LX704 class): wheelbase 2.3 m, track 1.6 m,
  /// ±35° steering at up to 20°/s.
  static VehicleParams Tractor();
  /// Seed 001's greenhouse transport vehicle: differential drive, track 0.5 m.
  static VehicleParams DiffDrive();
  /// A small four-wheel skid-steer robot. Its figures are chosen, not a source's: track 0.5 m,
  /// χ = 1.5 and the ICRs 0.05 m ahead of the axle centre (the load a little forward); the lags
  /// and limits of DiffDrive().
  static VehicleParams SkidSteer();

  /// The model is commanded by a yaw rate (diff_drive, skid_steer), not a steering angle.
  bool yaw_rate_commanded() const { return model != Model::kBicycle; }
  /// y_l − y_r: the track the yaw rate sees (track_m for a differential drive).
  double icr_track_m() const {
    return model == Model::kSkidSteer ? icr_expansion * track_m : track_m;
  }
  /// The reference point's lateral speed (m/s, left positive) at yaw rate ω: −x_v·ω (0 but for
  /// skid_steer).
  double lateral_speed_mps(double yaw_rate_radps) const {
    return model == Model::kSkidSteer ? -icr_offset_m * yaw_rate_radps : 0.0;
  }
};

/// Ground speeds of the left and right wheels (tracks) at forward speed `v_mps` and yaw rate
/// `yaw_rate_radps`: v ∓ ω·(y_l − y_r)/2 (the ICR kinematics of VehicleParams).
struct WheelGroundSpeeds {
  double left_mps = 0, right_mps = 0;
};
WheelGroundSpeeds WheelSpeedsOf(const VehicleParams& p, double v_mps, double yaw_rate_radps);

/// The body's motion from the wheels' (tracks') ground speeds: forward speed, lateral speed (left
/// positive) and yaw rate of the reference point (the inverse of WheelSpeedsOf, with v_y).
struct PlanarBodyVelocity {
  double forward_mps = 0, lateral_mps = 0, yaw_rate_radps = 0;
};
PlanarBodyVelocity BodyVelocityOf(const VehicleParams& p, double left_mps, double right_mps);

/// The speed variation of VehicleParams: factor(t) = 1 + x(t), x a first-order Gauss–Markov
/// process on a 0.1 s grid (exact discretisation, seeded), linearly interpolated. The same
/// parameters give the same function of time, however the integrator steps.
class SpeedVariation {
 public:
  SpeedVariation(double std, double tau_s, std::uint64_t seed);
  /// 1 + x(t) for t ≥ 0 (1 for a zero standard deviation). Extends the grid as needed.
  double Factor(double t_s);

 private:
  double std_, phi_;
  std::uint64_t state_;
  std::vector<double> x_;
};

/// One component of engine vibration, added to the body's pose about the reference point as a
/// sinusoid in time, so that the accelerometer and gyro truths see its exact derivatives.
struct VibrationComponent {
  double frequency_hz = 25;
  double heave_m = 0;    ///< displacement amplitude along body z
  double roll_rad = 0;   ///< roll angle amplitude
  double pitch_rad = 0;  ///< pitch angle amplitude
  double phase_rad = 0;
};

/// Engine vibration: a sum of sinusoids (empty = none).
struct VibrationConfig {
  std::vector<VibrationComponent> components;
};

}  // namespace hil::truth

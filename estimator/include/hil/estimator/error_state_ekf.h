#pragma once
/// @file
/// @system
/// name: ErrorStateEkf (loosely coupled GNSS/INS, closed loop)
/// input: bias-compensated IMU increments (predict, IMU rate); GNSS antenna position and velocity,
///        non-holonomic pseudo-measurements, heading (updates)
/// output: nominal NavState, biases, covariance, NIS of the last update, status flags
/// @endsystem
///
/// Error state (kNumUsedStates = 31 in a vector of kNumStates = 32, fixed-size):
///   δp (N, m) | δv (N, m/s) | φ (attitude error in N, rad; C_true = Exp(φ)·Ĉ) | δb_a (B, m/s²) |
///   δb_g (B, rad/s) | e_gnss (N, m: first-order Gauss–Markov GNSS position error, optional) |
///   δs (m/s: the vehicle's set speed, a slow random walk, optional) |
///   δd (m/s: the forward speed's deviation from the set speed, Gauss–Markov, optional) |
///   δμ (rad: pitch and yaw of the vehicle frame V in the IMU frame B, random constants, optional)
///   | δk_z (dimensionless: the z gyro's scale-factor error, a random constant, optional)
///   | δm_xz, δm_yz (rad: the x and y gyros' coupling to the z rate, random constants, optional)
///   | δt (s: the IMU tags' residual lag behind the fixes' time, a random constant, optional)
///   | δk_ay, δm_xy, δm_zy (the y accelerometer's scale error and the x and z accelerometers'
///   coupling to the y specific force: random constants, optional)
///   | δk_x, δk_y (the x and y gyros' scale-factor errors: random walks, optional)
///
/// The residual lag: after the tag lag navd found and took off (ImuTimeOffset) the INS at tag time
/// τ is the vehicle at τ − δt, so a fix at t is predicted as the INS's antenna at t plus its
/// velocity times δt, and the fix velocity as its velocity plus its acceleration times δt: H
/// columns v̂_ant and ā_N. A few milliseconds, where this first order holds (½·a·δt² is 4 µm at
/// 3 m/s² and 1.5 ms). ā_N is the INS's acceleration low-passed over 0.1 s: the last interval's
/// specific force carries the engine's vibration (m/s² on a tractor), with which the fix
/// velocities taught the lag noise (field_realism/parked_for_hours: RMSE 0.016 → 0.035 m).
///
/// The z gyro's scale factor: the gyro reads ω̃_z = (1 + k_z)·ω_z + b_z, the filter compensates
/// ω_z = (ω̃_z − b̂_z)/(1 + k̂_z), so φ̇ gains −Ĉ·ẑ·ω_z·δk_z (KF-GINS's gyro scale states, its z
/// row). A ground vehicle's headland turns (Θ = π each) make it observable: every turn leaves a
/// heading error k_z·Θ that the fixes show over the next row.
///
/// The x and y gyros' scale factors (off by default; `gyro_scale_xy_std`, and in `navd --kfgins`
/// from the configuration's gsstd, as KF-GINS estimates them): the x gyro reads
/// ω̃_x = (1 + k_x)·ω_x + m_xz·ω_z + b_x, the filter compensates
/// ω_x = (ω̃_x − b̂_x − m̂_xz·ω_z)/(1 + k̂_x), so φ̇ gains −Ĉ·x̂·ω_x·δk_x (y likewise). A car's roll
/// and pitch (its body in the turns and over the road, an IMU mounted pitched) make them show in
/// the tilt: on the real car drive_0708 KF-GINS without them had 30 s outages' maxima of 38.3 m
/// mean, with them 32.4 m (estimator.md, "The x and y gyros' scale factors"). A walker's gait
/// swings them both ways and taught them wrong (KF-GINS on walk_0827: 14.8 → 21.8 m): like the
/// couplings they are learnt only at speed (TurnStatesLearnable).
///
/// The x and y gyros' coupling to the z rate (the third column of the gyro triad's misalignment
/// matrix, its non-orthogonality): the x gyro reads ω̃_x = ω_x + m_xz·ω_z + b_x (y likewise), the
/// filter compensates ω_x = ω̃_x − b̂_x − m̂_xz·ω_z, so φ̇ gains −Ĉ·x̂·ω_z·δm_xz − Ĉ·ŷ·ω_z·δm_yz. In a
/// turn the coupling tilts the attitude (0.3° of it at 0.5 rad/s is 0.15°/s of roll), left and
/// right turns the opposite way; gravity in the accelerometers and the fixes show the tilt. The
/// couplings to the x and y rates multiply a ground vehicle's small roll and pitch rates and are
/// not states.
///
/// The accelerometer's errors in the lateral specific force: the y accelerometer reads
/// f̃_y = (1 + k_ay)·f_y + b_y, the x and z accelerometers f̃_x = f_x + m_xy·f_y + b_x and
/// f̃_z = f_z + m_zy·f_y + b_z; the filter compensates f_y = (f̃_y − b̂_y)/(1 + k̂_ay),
/// f_x = f̃_x − b̂_x − m̂_xy·f_y, f_z likewise, so δv̇ gains −Ĉ·(ŷ·δk_ay + x̂·δm_xy + ẑ·δm_zy)·f̄_y,
/// f̄_y the lateral force low-passed (two stages of 0.25 s: the ride's vibration, whose velocity
/// ripple the NHC sees, must not teach them). A ground vehicle's turns make them observable (the
/// centripetal f_y, 3 m/s² on a car at 6 m/s in a 12 m turn, left and right in turn; zero on the
/// rows), and they must be states where the y gyro's coupling to the z rate is: a turn's forward
/// and vertical force error otherwise reads as a pitch in the turn, i.e. as m_yz
/// (field_realism/imu_time_tag_lag seed 41: m̂_yz −0.50° against the emulated −0.22°, −0.28° with
/// them). Their other errors multiply f_x (small on a vehicle at constant speed) or gravity (a
/// constant the biases take).
///
/// The speed state is the vehicle model of a ground vehicle that holds its speed (cruise control,
/// constant throttle): the forward body velocity stays within `speed_dev_std_mps` of a set speed
/// that itself wanders as a random walk of `speed_rw_mps_rthz`. It gives the along-track velocity a
/// memory of tens of seconds, which a low-cost accelerometer (whose tilt drifts with the gyro
/// noise) cannot give, so the correlated GNSS error can be averaged over that long. Off (frozen,
/// zero covariance) when speed_rw_mps_rthz = 0.
/// With speed_dev_tau_s > 0 the deviation is a state of its own: a first-order Gauss–Markov process
/// of σ speed_dev_std_mps and correlation time speed_dev_tau_s (a governor's droop and wheel slip
/// wander over seconds), and the pseudo-measurement is "forward speed = s + d" with a small noise
/// (half that σ). Without it (τ = 0) the deviation is white at every update, which over-trusts
/// the set speed when the real speed wanders over seconds.
///
/// The mounting angles μ = (roll, pitch, yaw) rotate B into V: a vector's V coordinates are
/// C_VB·x_B with C_VB = Exp(μ)ᵀ (the vehicle's forward axis is Exp(μ)·x̂ in B). The
/// non-holonomic constraint and the speed model hold in V, not in B: an IMU is always mounted a
/// fraction of a degree off (Q. Chen et al., "Estimation of IMU Mounting Angles for Land
/// Vehicular GNSS/INS Integrated System", of the Wuhan group of KF-GINS, estimate the same two
/// angles from the NHC in a Kalman filter: github.com/QIJINCHEN/IMA-estimation). The roll is
/// unobservable from the NHC and stays 0. Off (frozen, zero covariance) when both prior σ are 0,
/// estimate_mount_angles is false or the NHC is off; an angle whose σ is 0 is held at 0.
///
/// The first 15 are the classic INS error states (paper 004); the three augmented states model the
/// time-correlated error of a standalone receiver (NEO-5M class, τ of seconds) so it is not
/// mistaken for vehicle motion. With gnss_error_tau_s = 0 they are frozen at zero (a plain 15-state
/// filter). Continuous error dynamics (ENU, Earth-fixed tangent frame):
///   δṗ = δv;  δv̇ = −[(Ĉf̂)×]φ − Ĉδb_a − 2[ω_IE×]δv;  φ̇ = −[ω_IE×]φ − Ĉδb_g;
///   δḃ = w (random walk);  ė = −e/τ + w (σ per axis: horizontal, horizontal, vertical).
/// Φ = I + F·dt per IMU interval; Joseph-form updates; every update is χ²-gated on its NIS.
/// The filter never throws or aborts on input; non-finite inputs are counted and rejected.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hil/estimator/mechanization.h"
#include "hil/estimator/vehicle_velocity_ripple.h"

namespace hil::estimator {

/// State-vector layout.
namespace ekf_index {
inline constexpr int kPos = 0;
inline constexpr int kVel = 3;
inline constexpr int kAtt = 6;
inline constexpr int kAccelBias = 9;
inline constexpr int kGyroBias = 12;
inline constexpr int kNumClassicStates = 15;  ///< δp … δb_g: the states that are always on
inline constexpr int kGnssError = 15;
inline constexpr int kSpeed = 18;
inline constexpr int kSpeedDev = 19;
inline constexpr int kMountPitch = 20;       ///< δμ_y: pitch of V in B (rad)
inline constexpr int kMountYaw = 21;         ///< δμ_z: yaw of V in B (rad)
inline constexpr int kGyroScaleZ = 22;       ///< δk_z: the z gyro's scale-factor error (fraction)
inline constexpr int kGyroCouplingX = 23;    ///< δm_xz: the x gyro's coupling to the z rate (rad)
inline constexpr int kGyroCouplingY = 24;    ///< δm_yz: the y gyro's coupling to the z rate (rad)
inline constexpr int kImuTimeResidual = 25;  ///< δt: the IMU tags' residual lag (s)
inline constexpr int kAccelScaleY = 26;  ///< δk_ay: the y accelerometer's scale error (fraction)
inline constexpr int kAccelCouplingXY = 27;  ///< δm_xy: the x accelerometer's coupling to f_y (rad)
inline constexpr int kAccelCouplingZY = 28;  ///< δm_zy: the z accelerometer's coupling to f_y (rad)
inline constexpr int kGyroScaleX = 29;       ///< δk_x: the x gyro's scale-factor error (fraction)
inline constexpr int kGyroScaleY = 30;       ///< δk_y: the y gyro's scale-factor error (fraction)
/// the states in use (the last index + 1), and the size of the filter's vectors and matrices: that
/// count made even (an unused last row and column, zero), so that Eigen's SSE packets of two
/// doubles tile every column (23 states left the covariance propagation unvectorised: +57 %
/// instructions over the 20 states before them; callgrind, ekf_benchmark seed004)
inline constexpr int kNumUsedStates = 31;
inline constexpr int kNumStates = kNumUsedStates + kNumUsedStates % 2;
}  // namespace ekf_index

using EkfVector = Eigen::Matrix<double, ekf_index::kNumStates, 1>;
using EkfMatrix = Eigen::Matrix<double, ekf_index::kNumStates, ekf_index::kNumStates>;

/// Filter parameters (constant for a run). Noise densities are continuous-time.
struct EkfParams {
  double accel_noise_mps2_rthz = 0.02;     ///< velocity random walk (m/s/√s)
  double gyro_noise_radps_rthz = 2e-4;     ///< angle random walk (rad/√s)
  double accel_bias_rw_mps3_rthz = 1e-4;   ///< accelerometer bias random walk
  double gyro_bias_rw_radps2_rthz = 1e-6;  ///< gyro bias random walk
  /// σ of the gyro's scale-factor and axis-misalignment error (rad of attitude error per rad
  /// turned, dimensionless; `[filter] gyro_scale_std`). Not white: a turn of Θ leaves an error s·Θ
  /// about every axis (roll and pitch from the misalignment, heading from the scale). Modelled as
  /// attitude noise per radian turned, s²·π rad²/rad, which reaches (s·π)² over a headland's half
  /// turn; nothing on a straight or while the attitude is held. 0 (off) by default: an IMU's scale
  /// error is its own (0.5 % on a consumer MEMS, far less on an industrial one: 0.005 cost the
  /// industrial-MEMS outage scenarios up to 30 % of their outage error). See estimator.md, "Turns
  /// and the gyro's scale".
  double gyro_scale_std = 0.0;
  double init_pos_std_m = 1.0;
  double init_vel_std_mps = 0.2;
  double init_roll_pitch_std_rad = 0.03;
  double init_yaw_std_rad = 0.2;
  double init_accel_bias_std_mps2 = 0.05;
  double init_gyro_bias_std_radps = 0.005;
  Eigen::Vector3d lever_arm_B_m = Eigen::Vector3d::Zero();  ///< GNSS antenna in the body frame
  double gnss_error_tau_s = 0.0;  ///< correlated GNSS position error τ (0 = off)
  /// its steady-state σ per horizontal axis (and up, unless:) at HDOP 1; fixes that report their
  /// HDOP scale it (SetGnssErrorModel), as a receiver's error scales with its geometry
  double gnss_error_std_m = 0.0;
  /// σ of the up component (0: gnss_error_std_m) at the nominal geometry: HDOP 1 and VDOP
  /// gnss_error_vdop_ref. A fix that reports its VDOP (NMEA GSA) scales it by VDOP /
  /// gnss_error_vdop_ref, one without by its HDOP; the float model keeps the same up/horizontal
  /// ratio
  double gnss_error_vertical_std_m = 0.0;
  /// the VDOP at which gnss_error_vertical_std_m holds (ours: 1.6, the VDOP/HDOP ratio of the
  /// emulated receivers' reference geometry, hdop_ref 1 and vdop_ref 1.6 in receiver_model.h, so
  /// that a fix without a VDOP, scaled by its HDOP, is scaled as one with VDOP = 1.6 · HDOP)
  double gnss_error_vdop_ref = 1.6;
  /// RTK float solutions (GGA quality 5): their own correlated error (decimetres, seconds); the
  /// filter switches to this model while fixes are float (0 = same model as fixed fixes).
  double gnss_float_error_tau_s = 0.0;
  double gnss_float_error_std_m = 0.0;
  /// Size the float model by the receiver's own horizontal σ (NAV-PVT hAcc / √2) when it is
  /// larger than gnss_float_error_std_m ([filter] gnss_float_error_from_receiver). Off by default:
  /// measured on the emulated F9P (vectors/scenarios/README.md "RTK rover") it halves navd's error
  /// in a float after a fixed phase (a calibrated INS) but lets an uncalibrated INS drift during a
  /// first float (rtk_f9p_base_20km: 0.64 m against the raw fixes' 0.47 m).
  bool gnss_float_error_from_receiver = false;
  double gnss_pos_std_floor_m = 0.005;  ///< lower bound on the white GNSS position σ
  double gnss_vel_std_floor_mps = 0.01;
  double nhc_std_mps = 0.0;         ///< non-holonomic constraint σ (0 = off)
  double speed_rw_mps_rthz = 0.0;   ///< set-speed random walk, m/s/√s (0 = speed model off)
  double speed_dev_std_mps = 0.05;  ///< forward speed's deviation from the set speed (1σ)
  double speed_dev_tau_s = 0.0;     ///< its correlation time (0: white, no state of its own)
  /// > 0: the NHC and the speed model see the vehicle velocity through a critically damped
  /// low-pass of this time constant (two stages, s), the ride's ripple left out
  /// (vehicle_velocity_ripple.h); 0 = the instantaneous velocity
  double vehicle_lowpass_tau_s = 0.0;
  double gate_sigma = 5.0;  ///< per-update χ² gate: NIS ≤ gate² · dof
  /// Prior σ of the IMU's mounting pitch and yaw against the vehicle (rad; `[filter]
  /// mount_pitch_std_deg`, `mount_yaw_std_deg`; 0 holds that angle at zero). 2° (our choice; the
  /// source gives none): a bracket or a console fitted by eye is within a degree or two. The pitch
  /// is learned from the NHC's vertical row against the tilt the accelerometer and the fixes show;
  /// the yaw only against the IMU's own heading, which the fixes show through accelerations: at
  /// low dynamics it takes over the heading information the NHC gave (estimator.md, "The IMU's
  /// mounting angles").
  double mount_pitch_std_rad = 2.0 * 0.017453292519943295;
  /// 0 by default (yaw held): measured on field_realism/tractor_engine_vibration (1 m/s, ±2 %
  /// speed) a 2° prior let the yaw wander 1–3° under a σ of 0.15–0.7° and doubled the RMSE
  /// (0.030 → 0.058 m, horizontal NEES 15); set it where the vehicle changes speed briskly.
  double mount_yaw_std_rad = 0.0;
  /// Estimate the mounting pitch and yaw (`[filter] mount_angle_estimation`, on by default):
  /// false holds them at zero (the NHC in the IMU frame, as before).
  bool estimate_mount_angles = true;
  /// Prior σ of the z gyro's scale-factor error, estimated as a random-constant state (fraction;
  /// `[filter] gyro_scale_z_std`; 0: not estimated, the gyro's scale taken as exact). 0.005 (our
  /// choice from data sheets: TDK ICM-42688-P ±0.5 % sensitivity tolerance, Bosch BMI088 ±0.5 %
  /// gyro sensitivity tolerance; estimator.md, "The z gyro's scale factor"). Unlike
  /// gyro_scale_std, which only widens the attitude's σ by the angle turned, this state learns
  /// the scale and corrects the turns with it.
  double gyro_scale_z_std = 0.005;
  /// Prior σ of the x and y gyros' scale-factor errors k_x, k_y (fraction; `[filter]
  /// gyro_scale_xy_std`; 0: not estimated, the default: navd's emulated IMUs and its walk showed
  /// no need of them) and their random walk (1/√s; `gyro_scale_xy_rw_rthz`): `navd --kfgins`
  /// takes KF-GINS's first-order Gauss–Markov σ (gsstd) as the prior and σ·√(2/τ) as the walk,
  /// as it does for the biases.
  double gyro_scale_xy_std = 0.0;
  double gyro_scale_xy_rw_rthz = 0.0;
  /// Prior σ of the x and y gyros' coupling to the z rate, m_xz and m_yz, each estimated as a
  /// random-constant state (rad; `[filter] gyro_z_coupling_x_std_deg`, `gyro_z_coupling_y_std_deg`,
  /// `gyro_z_coupling_std_deg` for both; 0: not estimated, that gyro taken as orthogonal to z).
  /// 0.3° for the y gyro: the consumer-MEMS misalignment of vectors/mcu/imu_error_model.md, 0.3°
  /// 1σ per off-diagonal coupling, the population's σ, which a random constant's prior should be
  /// (an industrial triad's 0.05° is well inside it); its pitch in the turns is well observed
  /// (the forward accelerometer sees g·θ), given the accelerometer's lateral-force states
  /// (accel_y_force_std; estimator.md, "The accelerometer in the turns"). The x gyro's is off by
  /// default: an IMU tag lag a few milliseconds off looks like an x coupling in every turn (0.12°
  /// per ms on field_realism/imu_time_tag_lag), and the state learned that instead and made the
  /// car worse (estimator.md, "The x and y gyros' coupling to the z rate").
  double gyro_z_coupling_x_std_rad = 0.0;
  double gyro_z_coupling_y_std_rad = 0.3 * 0.017453292519943295;
  /// Prior σ of the IMU tags' residual lag behind the fixes, estimated as a random-constant state
  /// (s; `[filter] imu_time_residual_std_s`; 0: not estimated). 0.01 s (our choice: the lag
  /// ImuTimeOffset reports has σ below its max_std_s, 10 ms, and wanders within ±5 ms of the
  /// true lag on the car; estimator.md, "The residual IMU tag lag").
  double imu_time_residual_std_s = 0.01;
  /// Prior σ of the y accelerometer's scale error k_ay and the x and z accelerometers' couplings
  /// m_xy, m_zy to the y specific force, estimated as three random-constant states while the x and
  /// y gyros' couplings to the z rate are (`[filter] accel_y_force_std`; fraction and rad; 0: not
  /// estimated). 0.005 (our choice: the consumer-MEMS scale σ 0.5 % and misalignment σ 0.3° =
  /// 0.0052 rad of vectors/mcu/imu_error_model.md, the ICM-42688-P's ±0.5 % sensitivity
  /// tolerance). The gyro's couplings need them (estimator.md, "The accelerometer in the turns").
  double accel_y_force_std = 0.005;
};

/// Health and status bit field.
enum EkfStatus : std::uint32_t {
  kStatusAligned = 1u << 0,
  kStatusGnssFused = 1u << 1,           ///< the last GNSS update passed the gate
  kStatusGnssRejected = 1u << 2,        ///< the last GNSS update was rejected
  kStatusDeadReckoning = 1u << 3,       ///< no GNSS fused for longer than the outage threshold
  kStatusReset = 1u << 4,               ///< position/velocity reset to GNSS after a long rejection
  kStatusBadInput = 1u << 5,            ///< a non-finite or out-of-range input was dropped
  kStatusCovarianceRepaired = 1u << 6,  ///< a covariance diagonal was clamped
  kStatusImuLost = 1u << 7,  ///< the IMU fell silent while fixes arrive: the solution is the fix
  /// the IMU is far outside its model (ImuUsabilityCheck): the solution is GNSS + vehicle model
  kStatusImuUnusable = 1u << 8,
};

/// Result of one measurement update.
struct UpdateResult {
  bool accepted = false;
  double nis = 0;  ///< innovationᵀ S⁻¹ innovation
  int dof = 0;
  /// The fading factor that would make this innovation consistent: (νᵀν − tr R) / tr(H P Hᵀ)
  /// (Xia, Rao, Ying and Shen 1994, the adaptive fading Kalman filter's one-step estimate);
  /// ≤ 1 when the covariance explains the innovation.
  double excess = 0;
};

/// A position fix's innovation ν and its covariance S = H P Hᵀ + R; nis = νᵀ S⁻¹ ν.
struct PositionInnovation {
  Eigen::Vector3d nu_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d S_m2 = Eigen::Matrix3d::Zero();
  double nis = 0;
  bool valid = false;
};

/// The error-state EKF. No allocation after construction.
class ErrorStateEkf {
 public:
  ErrorStateEkf() = default;
  explicit ErrorStateEkf(const EkfParams& params, const EarthModel& earth)
      : params_(params), earth_(earth), ripple_(params.vehicle_lowpass_tau_s) {}

  /// Sets the nominal state and the initial covariance from the parameters.
  void Initialize(const NavState& state);
  /// One IMU interval of raw increments (biases are removed here).
  void Predict(const Eigen::Vector3d& delta_angle_B_rad,
               const Eigen::Vector3d& delta_velocity_B_mps, double dt_s);
  /// GNSS antenna position in N with per-axis σ.
  UpdateResult UpdatePosition(const Eigen::Vector3d& p_antenna_N_m, const Eigen::Vector3d& std_m);
  /// A GNSS antenna position's innovation against the prediction (as UpdatePosition forms it) and
  /// its covariance H P Hᵀ + R, without an update.
  PositionInnovation PositionInnovationOf(const Eigen::Vector3d& p_antenna_N_m,
                                          const Eigen::Vector3d& std_m) const;
  /// Moves the nominal position by `dp_N_m` and adds `var_m2` per axis to its variance (the
  /// filter had followed a wrong RTK fix episode: RtkFixFrames).
  void ShiftPosition(const Eigen::Vector3d& dp_N_m, const Eigen::Vector3d& var_m2);
  /// GNSS antenna velocity in N with per-axis σ.
  UpdateResult UpdateVelocity(const Eigen::Vector3d& v_antenna_N_mps,
                              const Eigen::Vector3d& std_mps);
  /// Non-holonomic constraint: body lateral and vertical velocity are zero (ground vehicle).
  UpdateResult UpdateNonHolonomic();
  /// Speed model: the forward body velocity equals the set speed (within speed_dev_std_mps).
  UpdateResult UpdateSpeedModel();
  /// Starts the set speed at the current forward body velocity (alignment, after a reset).
  void ResetSetSpeed(double std_mps);
  /// Heading (yaw of body x, radians counter-clockwise from east) with σ.
  UpdateResult UpdateYaw(double yaw_enu_rad, double std_rad);
  /// Sets the correlated GNSS error model before a fix. `new_source`: the receiver changed its
  /// solution type (e.g. RTK fixed ↔ float): a larger σ adds the new, independent error's
  /// variance; a smaller σ means the old error is gone (ambiguities fixed), so the state restarts
  /// at zero with the new σ. Otherwise the same error process only changed its scale (the
  /// receiver's HDOP changed): the error is σ times a unit Gauss–Markov process, so the state and
  /// its covariance rows are rescaled by the ratio of the σ. No effect when the augmented states
  /// are off (gnss_error_tau_s = 0) or the model is unchanged.
  /// The up axis keeps the configured up/horizontal ratio (gnss_error_vertical_std_m /
  /// gnss_error_std_m).
  void SetGnssErrorModel(double tau_s, double std_m, bool new_source);
  /// The same with the up axis's σ of its own (`up_std_m`): a receiver's vertical error scales
  /// with its VDOP, not its HDOP. A rescaled process (`new_source` false) scales each axis's state
  /// and covariance rows by that axis's ratio.
  void SetGnssErrorModel(double tau_s, double std_m, double up_std_m, bool new_source);
  /// Zero-velocity update (the vehicle stands): v_N = 0 with σ per axis.
  UpdateResult UpdateZeroVelocity(double std_mps);
  /// Zero-angular-rate update (the vehicle stands): the mean raw gyro rate over a still interval
  /// is the gyro bias plus the Earth's rate in B, with σ per axis.
  UpdateResult UpdateZeroAngularRate(const Eigen::Vector3d& mean_raw_rate_B_radps,
                                     double std_radps);
  /// Attitude hold: while on, the vehicle is known to stand, so Predict turns the body with the
  /// Earth only (the gyro reading is bias and noise) and adds no angle random walk.
  void SetAttitudeHold(bool on) { attitude_hold_ = on; }
  bool attitude_hold() const { return attitude_hold_; }
  /// Fading memory (Fagin 1964; Sorenson and Sacks 1971): multiplies the covariance of the 15
  /// classic states (position … gyro bias) by `factor` ≥ 1; their cross-covariances with the
  /// augmented states by √factor (P ← D P D, D = diag(√factor·I₁₅, I₅): positive semi-definite).
  /// A bias variance that ends above its initial one (init_*_bias_std²) is scaled back to it with
  /// its row and column (again D P D): fading explains a wrong model, not a bias beyond its
  /// turn-on range (an unbounded gyro-bias σ let a standing vehicle's heading drift by 1°/s).
  void InflateCovariance(double factor);
  /// Fading after a gap in the fixes: the covariance the position fix's innovation shows missing,
  /// νᵀν − tr S (what InflateCovariance(λ) would add, (λ − 1) tr HPHᵀ, at most max_factor − 1 of
  /// it), is added in the shape of the process noise accumulated since the last accepted
  /// position fix (P ← P + g·G, g = missing / tr HGHᵀ): what was known at the gap's start stays
  /// known, the gap's growth is scaled to the evidence (estimator.md, "Recovering after an
  /// outage"). False (nothing changed) when there is no such noise or nothing is missing.
  bool FadeGapNoiseTo(const Eigen::Vector3d& p_antenna_N_m, const Eigen::Vector3d& std_m,
                      double max_factor);
  /// The gap's noise is carried from this long without an accepted position fix (the navigator's
  /// gap_after: no fix after a shorter gap is faded by FadeGapNoiseTo).
  void SetGapNoiseAfter(double seconds) { gap_noise_after_s_ = seconds; }
  /// Multiplies the IMU's white-noise densities' variances (accelerometer, gyro) in Predict (≥ 1;
  /// adapted by the navigator from its innovation statistics).
  void SetProcessNoiseScale(double scale) { q_scale_ = scale; }
  /// Multiplies the χ² gate's bound (gate_sigma² · dof) of the following updates (≥ 1; the
  /// navigator's median-NIS gate, RobustnessParams::gate_follows_median_nis).
  void SetGateScale(double scale) { gate_scale_ = std::max(1.0, scale); }
  /// Whether an update's NIS over `dof` is within the χ² gate (gate_sigma² · dof) times `scale`
  /// (at least 1): the test every update takes with SetGateScale's factor.
  bool WithinGate(double nis, int dof, double scale) const {
    return std::isfinite(nis) &&
           nis <= params_.gate_sigma * params_.gate_sigma * dof * std::max(1.0, scale);
  }
  double process_noise_scale() const { return q_scale_; }
  /// Further scales the accelerometer's white-noise and bias random-walk variances and the gyro's
  /// white-noise variance (≥ 1): the navigator's measure of how far the IMU is outside its model,
  /// from the GNSS velocity innovations (an engine's vibration shakes both sensors of a board).
  void SetAccelNoiseScale(double scale) { accel_scale_ = scale; }
  double accel_noise_scale() const { return accel_scale_; }
  /// Multiplies the non-holonomic constraint's noise variances (≥ 1; the navigator's measure of
  /// how far the vehicle is outside the constraint, from its innovations: NhcNoiseParams).
  void SetNhcNoiseScale(double scale) { nhc_scale_ = std::max(1.0, scale); }
  double nhc_noise_scale() const { return nhc_scale_; }
  /// A floor per body axis under the accelerometer's white-noise density² (m²/s³) in Predict: the
  /// density its own sample scatter shows (AccelScatter; 0: the configured density alone). The
  /// velocity's process noise is then C diag(q²) Cᵀ, no longer isotropic.
  void SetAccelNoiseFloor(const Eigen::Vector3d& density2_B_m2ps3) {
    accel_noise_floor_B_m2ps3_ = density2_B_m2ps3;
  }
  /// The largest axis's floor.
  double accel_noise_floor() const { return accel_noise_floor_B_m2ps3_.maxCoeff(); }
  /// The variance of the IMU's vibration velocity per body axis (VibrationVelocity): added to the
  /// noise of the non-holonomic (y, z) and speed-model (x) pseudo-measurements (zero: as
  /// configured).
  void SetVibrationVariance(const Eigen::Vector3d& var_B_mps2) {
    vibration_var_B_mps2_ = var_B_mps2;
  }
  /// Starts the bias estimates at known values (a dataset's initial biases), after Initialize.
  void SetBiases(const Eigen::Vector3d& accel_bias_B_mps2,
                 const Eigen::Vector3d& gyro_bias_B_radps);
  /// Resets position/velocity to a fix of the antenna (after a long rejection, or when the IMU
  /// returns from a loss; keeps attitude and biases). `pos_std_N_m`: the fix's white σ per axis;
  /// with the correlated GNSS error states on, the position also takes their variance (the fix
  /// holds that error too) with the matching negative covariance.
  void ResetPositionVelocity(const Eigen::Vector3d& p_N_m, const Eigen::Vector3d& v_N_mps,
                             const Eigen::Vector3d& pos_std_N_m, double vel_std_mps);

  /// Antenna position predicted from the nominal state.
  Eigen::Vector3d AntennaPosition() const;
  /// Antenna velocity predicted from the nominal state (lever-arm rotation included).
  Eigen::Vector3d AntennaVelocity() const;
  /// What a fix measures: the antenna position, the receiver's correlated error (when modelled)
  /// and the tag residual's displacement.
  Eigen::Vector3d PredictedFixPosition() const;
  /// A fix's noise covariance: its σ per axis, floored at gnss_pos_std_floor_m.
  Eigen::Matrix3d FixPositionNoise(const Eigen::Vector3d& std_m) const;

  /// Measurement Jacobians (public so tests can check them against finite differences).
  Eigen::Matrix<double, 3, ekf_index::kNumStates> PositionJacobian() const;
  Eigen::Matrix<double, 3, ekf_index::kNumStates> VelocityJacobian() const;
  Eigen::Matrix<double, 2, ekf_index::kNumStates> NonHolonomicJacobian() const;
  Eigen::Matrix<double, 1, ekf_index::kNumStates> SpeedModelJacobian() const;
  /// Applies an error-state vector to the nominal state (closed-loop correction).
  void InjectError(const EkfVector& dx);

  const NavState& state() const { return state_; }
  NavState& mutable_state() { return state_; }
  const EkfMatrix& covariance() const { return P_; }
  const Eigen::Vector3d& accel_bias() const { return ba_; }
  const Eigen::Vector3d& gyro_bias() const { return bg_; }
  const Eigen::Vector3d& gnss_error() const { return e_gnss_; }
  /// The variance of the receiver's correlated error as the model now has it (per ENU axis, at the
  /// last fix's geometry); zero with the correlated states off.
  Eigen::Vector3d GnssErrorModelVariance() const {
    return params_.gnss_error_tau_s > 0 ? GnssErrorVariance(gm_std_m_, gm_up_std_m_)
                                        : Eigen::Vector3d::Zero();
  }
  double set_speed_mps() const { return set_speed_; }
  double speed_deviation_mps() const { return speed_dev_; }
  /// The mounting angles (roll, pitch, yaw of V in B, rad; roll stays 0) and whether they are
  /// estimated.
  const Eigen::Vector3d& mount_angles_rad() const { return mount_rad_; }
  /// The z gyro's estimated scale-factor error k̂_z (fraction; 0 when not estimated).
  double gyro_scale_z() const { return gyro_scale_z_; }
  /// The x and y gyros' estimated scale-factor errors (k̂_x, k̂_y; 0 when not estimated).
  const Eigen::Vector2d& gyro_scale_xy() const { return gyro_scale_xy_; }
  bool gyro_scale_xy_estimated() const { return GyroScaleXyStatesOn(); }
  /// Start the gyros' scale-factor errors at these values (x, y, z; fraction; a KF-GINS
  /// configuration's initgyrscale): those not estimated are left at 0.
  void SetGyroScale(const Eigen::Vector3d& k);
  /// The x and y gyros' estimated coupling to the z rate (m̂_xz, m̂_yz, rad; 0 when not estimated).
  const Eigen::Vector2d& gyro_z_coupling_rad() const { return gyro_z_coupling_rad_; }
  /// The y accelerometer's estimated scale error and the x and z accelerometers' coupling to the
  /// y specific force (k̂_ay fraction, m̂_xy, m̂_zy rad; 0 when not estimated).
  const Eigen::Vector3d& accel_y_force_error() const { return accel_y_force_; }
  bool accel_y_force_estimated() const { return AccelForceStatesOn(); }
  bool gyro_z_coupling_estimated() const { return GyroCouplingStatesOn(); }
  /// The low-passed lateral specific force the last prediction gave Φ's columns of those states
  /// (B, m/s²; kLateralForceSmoothing_s).
  double lateral_force_lp_B_mps2() const { return f_y_lp_B_mps2_.y(); }
  /// The INS's acceleration low-passed over kAccelSmoothing_s (N, m/s²).
  const Eigen::Vector3d& smoothed_acceleration_N() const { return accel_lp_N_mps2_; }
  /// The IMU tags' estimated residual lag behind the fixes (s; 0 when not estimated).
  double imu_time_residual_s() const { return time_residual_s_; }
  /// The tags were moved by `shift_s` later (a lag taken off them: negative): the residual lag
  /// moves the other way (its σ stays).
  void ShiftImuTags(double shift_s);
  /// Restarts the random constants learned against the IMU's time base (the z gyro's scale, the x
  /// and y gyros' couplings to the z rate, the residual tag lag, the accelerometer's lateral-force
  /// errors, which a late tag's turn teaches too) at zero with their prior σ,
  /// uncorrelated with the other states: what they learned before a tag lag was found and taken
  /// off is the lag's error, not the gyro's.
  void RestartTimeBaseStates();
  /// The angle increment the filter integrates for a raw gyro increment over dt: the bias, the z
  /// gyro's scale and the x and y gyros' coupling to the z rate removed (B, rad).
  Eigen::Vector3d CompensatedAngle(const Eigen::Vector3d& delta_angle_B_rad, double dt) const;
  /// The velocity increment the filter integrates for a raw accelerometer increment over dt: the
  /// bias, the y accelerometer's scale and the x and z accelerometers' coupling to f_y removed
  /// (B, m/s).
  Eigen::Vector3d CompensatedVelocity(const Eigen::Vector3d& delta_velocity_B_mps, double dt) const;
  bool mount_angles_estimated() const { return MountStatesOn(); }
  /// C_VB, the rotation from the IMU frame into the vehicle frame (identity when off).
  const Eigen::Matrix3d& vehicle_from_imu() const { return C_VB_; }
  const Eigen::Vector3d& last_gyro_rate_B() const { return w_B_; }
  const EkfParams& params() const { return params_; }
  const EarthModel& earth() const { return earth_; }
  std::uint32_t repairs() const { return repairs_; }

 private:
  /// the prior variances of the states RestartTimeBaseStates restarts (those that are on)
  void SetTimeBasePriors();
  template <int M>
  UpdateResult Update(const Eigen::Matrix<double, M, 1>& innovation,
                      const Eigen::Matrix<double, M, ekf_index::kNumStates>& H,
                      const Eigen::Matrix<double, M, M>& R);
  /// The update over P's first N states (N = 15 when the augmented states are off).
  template <int N, int M>
  UpdateResult UpdateOf(const Eigen::Matrix<double, M, 1>& innovation,
                        const Eigen::Matrix<double, M, N>& H, const Eigen::Matrix<double, M, M>& R);
  /// P ← Φ P Φᵀ for one IMU interval, by Φ's blocks (no dense 20 × 20 product).
  void PropagateCovariance(const Eigen::Matrix3d& C, double dt, double gm_decay, double dev_decay);
  /// Φ's 3 × 3 blocks for one interval, transposed (the propagation's products run on P's
  /// columns): A = I − 2[ω_IE×]dt, B = −[f_N×]dt, D = I − [ω_IE×]dt, G = −Ĉdt (Gg: in the
  /// attitude rows, zero while the attitude is held); and Φ's columns of the turn states (Gk in
  /// the attitude rows, Ga in the velocity rows; only Gk's first while they are not learnable).
  /// Φ's columns of the turn states for one interval (error_state_ekf.cc, TurnStateColumns).
  struct TurnColumns {
    Eigen::Matrix3d Gk = Eigen::Matrix3d::Zero();  ///< φ rows: δk_z, δm_xz, δm_yz
    Eigen::Matrix3d Ga = Eigen::Matrix3d::Zero();  ///< δv rows: δk_ay, δm_xy, δm_zy
    Eigen::Matrix<double, 3, 2> Gs = Eigen::Matrix<double, 3, 2>::Zero();  ///< φ rows: δk_x, δk_y
    bool learnable = false;
  };
  static TurnColumns TurnStateColumns(const Eigen::Matrix3d& C, const Eigen::Vector3d& w_B_radps,
                                      double f_y_mps2, bool attitude_hold, bool learnable,
                                      double dt);
  struct PhiBlocks {
    Eigen::Matrix3d At, Bt, Dt, Gt, Ggt;
    TurnColumns turn;
  };
  PhiBlocks TransposedPhiBlocks(const Eigen::Matrix3d& C, double dt) const;
  /// The same over P's first N states (N = 15 when the augmented states are off).
  /// After a fading: attitude and bias variances above their initial ones scaled back to them,
  /// with their rows and columns.
  void ClampFadedVariances();
  template <int N, typename Block>
  void PropagateCovarianceOf(Block P, const PhiBlocks& phi, double dt, double gm_decay,
                             double dev_decay) const;
  /// The IMU's white noise (and the biases' random walks) of one interval added to P's classic
  /// block.
  template <typename Block>
  void AddImuNoise(Block P, const Eigen::Matrix3d& C, double turned_rad, double dt,
                   bool bias_walks) const;
  /// The gap's white noise (gap_noise_) over one interval: counted from the last accepted
  /// position fix, carried once gap_noise_after_s_ has passed without one.
  void AccumulateGapNoise(const Eigen::Matrix3d& C, double turned_rad, double dt);
  void RestartGapNoise();
  /// The correlated-GNSS-error, speed-model, mounting-angle or gyro-triad states are on: P's rows
  /// after the classic ones may be non-zero.
  bool AugmentedStatesOn() const {
    return params_.gnss_error_tau_s > 0 || params_.speed_rw_mps_rthz > 0 || MountStatesOn() ||
           GyroScaleStateOn() || GyroCouplingStatesOn() || TimeResidualStateOn() ||
           AccelForceStatesOn() || GyroScaleXyStatesOn();
  }
  /// The x and y gyros' scale factors are estimated.
  bool GyroScaleXyStatesOn() const { return params_.gyro_scale_xy_std > 0; }
  /// The accelerometer's lateral-force errors (δk_ay, δm_xy, δm_zy) are estimated.
  bool AccelForceStatesOn() const { return params_.accel_y_force_std > 0; }
  /// The IMU tags' residual lag is estimated.
  bool TimeResidualStateOn() const { return params_.imu_time_residual_std_s > 0; }
  /// The fixes teach the residual lag now: at speed. Standing or at a walk its v·δt is below the
  /// fixes' noise and their slow wander taught it instead (field_realism/parked_for_hours: δ̂t
  /// walked to the 0.1 s clamp over four parked hours and put 10 cm along the track once the
  /// tractor drove off; learning in turns only left the car at fused/raw 1.54).
  bool TimeResidualLearnable() const;
  /// The turns teach the x and y gyros' couplings to the z rate and the accelerometer's
  /// lateral-force states now: at speed (kTurnStatesMinSpeed_mps), now and at the last accepted
  /// position fix. Otherwise Φ and H leave their columns out: the states keep what they learned
  /// and compensate with it.
  bool TurnStatesLearnable() const;
  /// The z gyro's scale factor is estimated.
  bool GyroScaleStateOn() const { return params_.gyro_scale_z_std > 0; }
  /// The x and y gyros' coupling to the z rate is estimated.
  bool GyroCouplingStatesOn() const {
    return params_.gyro_z_coupling_x_std_rad > 0 || params_.gyro_z_coupling_y_std_rad > 0;
  }
  /// The mounting pitch and yaw are estimated (they need the NHC to be observable).
  bool MountStatesOn() const {
    return params_.estimate_mount_angles && params_.nhc_std_mps > 0 &&
           (params_.mount_pitch_std_rad > 0 || params_.mount_yaw_std_rad > 0);
  }
  /// The body velocity in the vehicle frame, C_VB·Ĉᵀ·v̂.
  Eigen::Vector3d VehicleVelocity() const;
  /// Rows of the vehicle-frame velocity's Jacobian (δv, φ and δμ columns).
  Eigen::Matrix<double, 3, ekf_index::kNumStates> VehicleVelocityJacobian() const;
  void Symmetrize();
  void SymmetrizeBlock(int first, int end);
  /// A negative or non-finite variance: its row and column restart (counted in repairs_).
  void RepairDiagonal();
  /// Stationary variances (E, N, U) of the correlated GNSS error for its horizontal and up σ.
  static Eigen::Vector3d GnssErrorVariance(double horizontal_std_m, double up_std_m);

  EkfParams params_;
  EarthModel earth_;
  NavState state_;
  MechanizationMemory memory_;
  Eigen::Vector3d ba_ = Eigen::Vector3d::Zero(), bg_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d e_gnss_ = Eigen::Vector3d::Zero();
  double gm_tau_s_ = 0.0, gm_std_m_ = 0.0;  // current correlated GNSS error model (horizontal σ)
  double gm_up_ratio_ = 1.0;                // configured up σ / horizontal σ
  double gm_up_std_m_ = 0.0;                // current correlated GNSS error model's up σ
  double set_speed_ = 0.0;                  // speed model: the vehicle's set speed (m/s)
  double speed_dev_ = 0.0;                  // speed model: forward speed minus set speed (m/s)
  Eigen::Vector3d mount_rad_ = Eigen::Vector3d::Zero();  // μ: V in B (roll, pitch, yaw)
  Eigen::Matrix3d C_VB_ = Eigen::Matrix3d::Identity();   // Exp(μ)ᵀ
  double gyro_scale_z_ = 0.0;                            // k̂_z: the z gyro's scale error
  Eigen::Vector2d gyro_z_coupling_rad_ = Eigen::Vector2d::Zero();  // m̂_xz, m̂_yz
  Eigen::Vector2d gyro_scale_xy_ = Eigen::Vector2d::Zero();        // k̂_x, k̂_y
  double time_residual_s_ = 0.0;  // δ̂t: the IMU tags' residual lag behind the fixes
  Eigen::Vector3d accel_y_force_ = Eigen::Vector3d::Zero();  // k̂_ay, m̂_xy, m̂_zy
  // the acceleration's low-pass time constant: a 10 Hz fix interval, over which an engine's
  // orders (tens of Hz) average out (chosen here)
  static constexpr double kAccelSmoothing_s = 0.1;
  // 2 m/s (chosen here): above a tractor's working speed, where v·δt of a few milliseconds is
  // below an RTK fix's noise (5 mm at 1 m/s and 5 ms)
  static constexpr double kResidualMinSpeed_mps = 2.0;
  // 2 m/s (chosen here): a car's turns at speed; below it the motion's own lateral force and yaw
  // swing (a walker's gait; a tractor's ride, 0.6 m/s² lateral, against its 0.3 m/s² of
  // centripetal force at 1 m/s) taught the couplings and the lateral-force states instead:
  // ci/real_walk_0827's navd + NHC, RTK present, 0.101 → 0.209 m with them learned at any speed
  static constexpr double kTurnStatesMinSpeed_mps = 2.0;
  // the speed at the last accepted position fix too: in an outage the INS's own speed error put a
  // walker above 2 m/s, and the free INS taught the states (real_walk_0827's navd + NHC, 30 s
  // outages: worst window 33.8 → 54.0 m)
  double speed_at_fix_mps_ = 0.0;  // horizontal speed after the last accepted position fix
  Eigen::Vector3d accel_lp_N_mps2_ = Eigen::Vector3d::Zero();  // ā_N (kAccelSmoothing_s)
  Eigen::Vector3d w_B_ = Eigen::Vector3d::Zero();              // last compensated angular rate
  Eigen::Vector3d f_N_ = Eigen::Vector3d::Zero();              // last specific force in N
  // the compensated specific force along the body's y axis through two first-order low-passes of
  // kLateralForceSmoothing_s each (the first stage, the second: what Φ's columns of the
  // accelerometer's lateral-force states take)
  Eigen::Vector2d f_y_lp_B_mps2_ = Eigen::Vector2d::Zero();
  // 0.25 s (chosen here): a ride at 1.5 Hz passes at 0.15 (the tractor's 1.2-2.5 Hz roll mode, the
  // car's ride from 0.8 Hz), a turn's centripetal force (seconds) with about 0.5 s of delay. With
  // the instantaneous force the states took the ride's velocity ripple, which the NHC sees, for a
  // scale error: k̂_ay walked to its 10 % clamp on field_realism/tractor_engine_vibration (outage
  // max 0.106 → 0.127 m on seed 5); 0.1 s left seed 5 at 0.112 m, 0.25 and 0.5 s at 0.105 m.
  static constexpr double kLateralForceSmoothing_s = 0.25;
  EkfMatrix P_ = EkfMatrix::Identity();
  /// The process noise P took since the last accepted position fix, carried by the same Φ (the
  /// classic states'; FadeGapNoiseTo)
  Eigen::Matrix<double, ekf_index::kNumClassicStates, ekf_index::kNumClassicStates> gap_noise_ =
      Eigen::Matrix<double, ekf_index::kNumClassicStates, ekf_index::kNumClassicStates>::Zero();
  bool gap_noise_on_ = false;          // gap_noise_ is being carried
  double since_fix_s_ = 0.0;           // time since the last accepted position fix
  double turned_since_fix_rad_ = 0.0;  // the angle turned since then
  double gap_noise_after_s_ = 1.5;     // SetGapNoiseAfter
  std::uint32_t repairs_ = 0;
  double q_scale_ = 1.0;      // process-noise scale (SetProcessNoiseScale)
  double gate_scale_ = 1.0;   // the gate bound's factor (SetGateScale)
  double accel_scale_ = 1.0;  // SetAccelNoiseScale
  double nhc_scale_ = 1.0;    // SetNhcNoiseScale
  Eigen::Vector3d accel_noise_floor_B_m2ps3_ = Eigen::Vector3d::Zero();  // SetAccelNoiseFloor
  Eigen::Vector3d vibration_var_B_mps2_ = Eigen::Vector3d::Zero();       // SetVibrationVariance
  VehicleVelocityRipple ripple_;                                         // vehicle_lowpass_tau_s
  bool attitude_hold_ = false;                                           // SetAttitudeHold
};

}  // namespace hil::estimator

#pragma once
/// @file
/// @system
/// name: Navigator (the transport-free estimator core)
/// input: Push(ImuSample) at IMU rate, Push(GnssSample) at GNSS rate (late, out of order, any mix),
///        Push(HeadingSample) (compass); all on GPS time from the drivers
/// output: Output() — the solution at the newest IMU time (output predictor); covariance(),
///         status(), stats()
/// @endsystem
///
/// Delay handling: a fusion horizon. The filter runs `fusion_horizon` behind the newest IMU
/// sample, so a GNSS fix that arrives up to that late is still fused at its own time of validity
/// (the IMU interval that contains it is split there). Output() re-propagates the filter state
/// through the IMU samples still waiting in the buffer (the output predictor). Samples older than
/// the filter time are counted as late and dropped; IMU samples out of order are dropped.
/// Waiting for GNSS: with `gnss_max_latency` above the horizon, the filter also holds at the
/// time of the next expected GNSS epoch (last fix time + the measured fix period) until that fix
/// arrives or the newest IMU sample is `gnss_max_latency` past it. A slow serial link (NMEA at
/// 9600 baud completes GGA ≈ 0.3 s after the epoch) or a host that reads its devices unevenly
/// then costs no fixes, while the filter runs only `fusion_horizon` behind when fixes are on
/// time. Once the wait for a due epoch has run out the fixes are missing (an outage): the filter
/// runs `fusion_horizon` behind again until a fix arrives, so that the output predictor does not
/// carry the free INS over the whole wait.
/// Alignment: levelling from the mean specific force, heading from the GNSS course once the speed
/// exceeds `align_min_speed_mps`, or from the compass. Fixed-size buffers, no allocation.
/// IMU loss: when the IMU has been silent for `imu_timeout` of GNSS time while fixes keep coming
/// (a dead sensor, a cut cable or bus) and at least 4 fixes arrived since the last IMU sample (a
/// host that reads its links in bursts can see GNSS time run ahead for a moment without any loss),
/// Output() is the newest fix itself, flagged kStatusImuLost,
/// so a host keeps producing solutions; when samples return after such a gap, the filter restarts
/// its position and velocity at the next fix (its state could not be propagated through the gap),
/// and until then Output() stays the fix.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/accel_scatter.h"
#include "hil/estimator/error_state_ekf.h"
#include "hil/estimator/fix_velocity_ripple.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/gnss_step_check.h"
#include "hil/estimator/gnss_velocity_noise.h"
#include "hil/estimator/imu_time_offset.h"
#include "hil/estimator/imu_usability_check.h"
#include "hil/estimator/innovation_monitor.h"
#include "hil/estimator/planar_filter.h"
#include "hil/estimator/ring_buffer.h"
#include "hil/estimator/rtk_fix_check.h"
#include "hil/estimator/rtk_fix_frames.h"
#include "hil/estimator/samples.h"
#include "hil/estimator/stationary_detector.h"
#include "hil/estimator/vehicle_model_filter.h"
#include "hil/estimator/vibration_velocity.h"

namespace hil::estimator {

/// Filter mode (navd's [filter] mode).
enum class NavMode {
  kEkf,        ///< error-state GNSS/INS EKF (the product)
  kPlanar2d,   ///< seed 000's planar Kalman filter
  kGnssOnly,   ///< the GNSS fix, passed through
  kImuOnly,    ///< dead reckoning after alignment (no GNSS updates)
  kMultiGnss,  ///< several receivers (seed 000: three): centroid position and heading from their
               ///< geometry
};
/// Mode name as used in the configuration and the JSON output.
const char* NavModeName(NavMode m);
/// Mode from its name; nullopt when unknown.
std::optional<NavMode> NavModeFromName(const char* name);
/// Modes that run on IMU samples (ekf, planar2d, imu_only): the one predicate for hosts too.
bool UsesImu(NavMode m);

/// Receivers the multi-receiver mode combines at most.
inline constexpr int kMaxGnssAntennas = 4;

/// Consistency-driven robustness of the EKF (estimator.md, "Consistency and robustness").
struct RobustnessParams {
  /// Fade to fixes (on by default, issue 39): a fix that is at least the reject_fade_count-th
  /// rejected in a row over reject_fade_after, or the first after a gap_after without fixes, is
  /// fused against the covariance faded by its own excess factor, with the GNSS step check that
  /// tells a receiver glitch from a wrong model. Off: a gate alone, and after
  /// reset_after_rejected a reset of position and velocity (walk_0827: 128 of 530 RTK fixes
  /// rejected, 6 resets, 0.159 m RMSE, against 0.034 m with it on; see estimator.md).
  bool fade_to_fixes = true;
  /// Adapt the process noise to the GNSS position NIS window (above its χ² band: the IMU noise is
  /// scaled up; implies fade_to_fixes). Off by default: scaling the isotropic IMU noise by a
  /// window's NIS also inflates the tilt and heading noise where the excess is in one axis
  /// (walk_0827: a walker's vertical innovations; 15 s outages 6.3 m worst, against 2.8 m
  /// without the scaling), and before the step check it took variant_glitch_5m's lasting 5 m
  /// jump for a wrong model (4.4 m RMSE against 0.022 m); see estimator.md.
  bool adaptive = false;
  /// Fading to fixes (and the step check) in use.
  bool FadesToFixes() const { return fade_to_fixes || adaptive; }
  int reject_fade_count = 3;                     ///< this many rejected fixes in a row …
  Nanoseconds reject_fade_after{2'000'000'000};  ///< … over this long: fade to the next one
  /// a fix after this long without any fix is gated against a covariance faded to it
  Nanoseconds gap_after{1'500'000'000};
  /// The fading after a gap (gap_after without fixes) scales the IMU's white noise accumulated
  /// since the last accepted position fix instead of the whole covariance
  /// (ErrorStateEkf::FadeGapNoiseTo): the fix's excess says the noise model grew the covariance
  /// too little over the gap, not that what the filter knew when the gap began (attitude,
  /// biases) was wrong. On by default (issue 39: walk_0827's 10 s outages 20 s after another,
  /// 3 of 36 windows above 2 × KF-GINS → 0; estimator.md, "Recovering after an outage").
  bool fade_gap_noise = true;
  /// Recovery after a gap: after the first fix after gap_after without fixes (gated, and faded
  /// to as above), the fixes are fused against the filter's own covariance without the gate
  /// until gap_recovery_passes in a row would have passed it, or gap_recovery_max has passed.
  /// The covariance the INS propagated over the gap holds the gap's drift in the shape the INS
  /// errors give it (position ≈ velocity·t/2 for a bias or tilt error); the gap's fading, in the
  /// white noise's shape, left the velocity metres per second wrong, the next fixes were rejected
  /// and their λ P fading made the attitude diverge (the real car drive_0708, 15 and 30 s
  /// outages: km, 26 resets; estimator.md, "The fixes after a gap's first"). A suspect RTK fix
  /// is still held off (RtkFixCheck); a receiver that jumps within a recovery is believed.
  /// Zero: off.
  Nanoseconds gap_recovery_max{5'000'000'000};
  int gap_recovery_passes = 3;           ///< fixes in a row within the gate that end a recovery
  double max_fading_factor = 1e6;        ///< largest covariance factor of one fading step
  double max_process_noise_scale = 1e4;  ///< largest process-noise scale (σ ×100)
  double max_scale_step = 10.0;          ///< largest change of that scale per window
  double nis_clip_per_dof = 9.0;         ///< NIS per degree of freedom is clipped here (3σ)
  /// GNSS consistency (with FadesToFixes()): a rejected fix whose increment from the previous fix
  /// the INS displacement does not explain (GnssStepCheck) starts a receiver glitch. Its fixes are
  /// rejected without feeding the adaptation (no fading, no window, no reset) until a fix passes
  /// the gate, the fixes step back (the filter then fades to them as after a gap), or the glitch
  /// has lasted glitch_hold: then it is persistent evidence, and the fixes are handled as any
  /// rejected fixes (fading after reject_fade_after, the reset as the last resort).
  GnssStepParams step;
  Nanoseconds glitch_hold{10'000'000'000};
  /// The GNSS position gate against the innovation spread the filter has shown, not the one it
  /// claims (on by default, issue 39): the gate's χ² bound is multiplied by the position
  /// window's median NIS per degree of freedom over χ²(3)'s median per degree of freedom (0.789),
  /// at least 1, once the window holds gate_median_min_count updates. The median of the window
  /// (clipped NIS, rejected fixes included) is not moved by the few wild fixes the gate is there
  /// for, but follows a covariance that is too small for every fix (real walk_0827: position
  /// NEES 99; over 101 single 10 s outages navd's windows above 2 × KF-GINS 23 → 1, mean of
  /// the maxima 1.98 → 1.46 m; estimator.md, "The gate and the spread the filter has shown").
  bool gate_follows_median_nis = true;
  int gate_median_min_count = kInnovationWindow;
};

/// The accelerometer against its noise model, as the GNSS velocity sees it (estimator.md, "An IMU
/// outside its noise model"). A velocity innovation over a fix interval is the accelerometer's
/// error integrated (and the tilt's, times g): when the GNSS velocity window's mean and median NIS
/// per degree of freedom are both above `raise_nis_per_dof` (far above the χ² band, whose top is
/// 1.39 for 20 three-axis updates), the accelerometer's white-noise and bias random-walk variances
/// and the gyro's white-noise variance are scaled by the window's mean excess factor
/// (ErrorStateEkf::UpdateResult::excess; at most ×`max_step` per window, ×`max_scale` in all) and
/// the window restarts; a window whose mean is below 1 scales them back (never below the configured
/// noise). Innovation-based adaptive estimation of the process noise (Mohamed and Schwarz, J.
/// Geodesy 73, 1999), on the sensor the velocity observes. Once raised, the GNSS position window
/// adapts the IMU noise as well (RobustnessParams::adaptive's rule): the velocity has shown that
/// the IMU, not the receiver, is outside its model. A source without velocities (navd --kfgins)
/// never raises it.
struct ImuNoiseParams {
  bool enabled = true;
  double raise_nis_per_dof = 4.0;  ///< window mean and median above this: outside the model
  double max_step = 10.0;          ///< largest change of the scale per window
  double max_scale = 1e4;          ///< largest variance scale (σ ×100)
};

/// The non-holonomic constraint against its own innovations (estimator.md, "When the NHC's premise
/// fails"). The constraint (the vehicle's lateral and vertical velocity zero) is a model of the
/// vehicle, not a sensor: a walker's sway and crab, a skidding vehicle break it. While the GNSS is
/// present (a fix fused within RobustnessParams::gap_after: the fixes hold the velocity, so a miss
/// is the constraint's), NHC updates whose window (20 updates, 2 s at 10 Hz) has its mean and
/// median NIS per degree of freedom both above `raise_nis_per_dof`, `persist_updates` updates in a
/// row, show the vehicle outside it: the constraint's noise variances are scaled by the window's
/// mean NIS per degree of freedom (at most ×`max_step` per window, ×`max_scale` in all) and the
/// window restarts. Once raised, a window above its 95 % χ² band with median above 1 raises it
/// further and a window below its band lowers it, by at most ÷`max_lower_step` (never below 1):
/// the scale follows the innovations, the innovation-based adaptive estimation of the noise
/// (Mohamed and Schwarz, J. Geodesy 73, 1999), bounded. During an outage the scale is held:
/// without fixes the constraint's misses cannot be told from the INS's drift.
struct NhcNoiseParams {
  bool enabled = true;
  /// window mean and median above this: outside the constraint (5, chosen: 3.4 × the band's top,
  /// 1.48 for 20 two-row updates; most updates missing by more than 2σ per row)
  double raise_nis_per_dof = 5.0;
  /// … for this many updates in a row (one window length, 2 s at 10 Hz; chosen): the emulated
  /// vehicles the constraint holds for get there for 10 updates in a row at most
  /// (field_realism/tractor_engine_vibration: an engine's vibration against a 2 cm/s constraint;
  /// the others stay below 0.6), the walk_0827 walker for up to 209 (its crab and sway against
  /// 10 cm/s)
  int persist_updates = 20;
  double max_step = 10.0;  ///< largest raise of the scale per window
  /// largest lowering per window: 1.1 (chosen), ÷10 from the scale's top in about 50 s. A vehicle
  /// that pauses or goes straight for a few seconds has not come back into the constraint, and a
  /// scale too small going into an outage costs more than one too large (walk_0827 sweep, single
  /// 10 s outages, mean of the maxima and the worst window against navd without the constraint:
  /// lowered by up to ÷2 1.49 m, 4.9 ×; ÷1.1 1.48 m, 2.8 ×; never 1.51 m, 2.8 ×; measured with the
  /// first raise at 6 at once).
  double max_lower_step = 1.1;
  double max_scale = 1e4;  ///< largest variance scale (σ ×100)
};

/// The aid sources whose innovations are monitored.
enum AidSource : int {
  kAidGnssPosition = 0,
  kAidGnssVelocity,
  kAidNonHolonomic,
  kAidZeroVelocity,
  kAidZeroAngularRate,
  kNumAidSources,
};
/// Name in navd's health output.
const char* AidSourceName(int source);

struct NavigatorParams {
  NavMode mode = NavMode::kEkf;
  EkfParams ekf;
  PlanarFilterParams planar;
  /// Largest GNSS delay that is still fused in time.
  Nanoseconds fusion_horizon{250'000'000};
  /// Longest wait for an expected GNSS epoch (≤ the filter's IMU buffer; 0 or ≤ the horizon: off).
  Nanoseconds gnss_max_latency{0};
  double align_min_speed_mps = 0.2;                 ///< GNSS course trusted for heading above this
  Nanoseconds nhc_period{100'000'000};              ///< non-holonomic update period (if enabled)
  Nanoseconds outage_flag_after{1'500'000'000};     ///< dead-reckoning flag after this without GNSS
  Nanoseconds reset_after_rejected{5'000'000'000};  ///< reset to GNSS after rejections this long
  Nanoseconds imu_timeout{1'000'000'000};  ///< IMU modes: fall back to the fixes after this
  bool use_gnss_velocity = true;
  /// The fix velocity is compared with the INS's velocity less its ripple at the fix instants
  /// (FixVelocityRipple; estimator.md, "The INS's ripple at the fix instants").
  bool fix_velocity_ripple = true;
  /// EKF mode: the σ of a fix velocity whose receiver reports none (GnssSample::
  /// vel_std_configured, NMEA) is learned from its innovations, never above the configured one
  /// (GnssVelocityNoise, aid_sources/gnss_velocity_control.cc; `[filter] gnss_velocity_noise`).
  GnssVelocityNoiseParams gnss_vel_noise;
  RobustnessParams robust;
  StationaryParams stationary;
  /// EKF mode: the accelerometer's noise follows the GNSS velocity innovations when they show it
  /// far outside its model (aid_sources/imu_noise_control.cc).
  ImuNoiseParams imu_noise;
  /// EKF mode: the non-holonomic constraint's noise follows its innovations when they show the
  /// vehicle outside it (aid_sources/nhc_noise_control.cc).
  NhcNoiseParams nhc_noise;
  /// EKF mode: the IMU's vibration velocity (VibrationVelocity: above the corner of this time
  /// constant) widens the non-holonomic and speed-model pseudo-measurements by its variance,
  /// averaged over vibration_mean_tau_s; 0: off.
  double vibration_tau_s = 0.0;
  double vibration_mean_tau_s = 2.0;
  /// EKF mode: the accelerometer's white noise is at least what its own sample scatter shows
  /// (AccelScatter, averaged over this long; 0: off).
  double accel_scatter_tau_s = 10.0;
  /// … for an IMU read out at most this fast (ours: 50 Hz, a Nyquist frequency of 25 Hz, below a
  /// ground vehicle's engine and ride vibration, which such an IMU can only alias)
  double accel_scatter_max_rate_hz = 50.0;
  /// EKF mode: the IMU tags' lag behind GNSS time, estimated online (ImuTimeOffset) and taken off
  /// the IMU tags once conclusive (aid_sources/imu_lag_control.cc).
  ImuTimeOffsetParams imu_lag;
  /// EKF mode: a new RTK fix episode that contradicts the aided filter from its first fix is
  /// suspect (a wrong integer fix) and its positions are not fused (RtkFixCheck,
  /// aid_sources/rtk_fix_control.cc).
  RtkFixCheckParams rtk_fix;
  /// EKF mode: the accelerometer against the GNSS (ImuUsabilityCheck); while it is unusable the
  /// solution is the GNSS + vehicle-model filter (VehicleModelFilter; its lever arm, correlated
  /// GNSS error and, when the speed model is on, speed random walk are the EKF's), the EKF runs on
  /// beside it (aid_sources/imu_usability_control.cc).
  ImuUsabilityParams imu_usability;
  VehicleModelParams fallback_vehicle;
  /// Multi-receiver mode: antenna positions in the body frame, one column per receiver
  /// (GnssSample::antenna); the first `multi_antenna_count` columns are used (seed 000: three on a
  /// 3 m circle). At least two antennas with distinct horizontal positions give a heading.
  Eigen::Matrix<double, 3, kMaxGnssAntennas> multi_antenna_B_m =
      Eigen::Matrix<double, 3, kMaxGnssAntennas>::Zero();
  int multi_antenna_count = 3;
};

/// The vehicle-model fallback's parameters: `fallback_vehicle` with the EKF's lever arm and
/// correlated GNSS error, and its speed random walk when the speed model is on.
VehicleModelParams FallbackVehicleParams(const NavigatorParams& p);

/// Counters a host reports as health.
struct NavigatorStats {
  std::uint64_t imu_samples = 0, imu_out_of_order = 0, imu_overflow = 0, imu_gaps = 0;
  std::uint64_t gnss_samples = 0, gnss_late = 0, gnss_fused = 0, gnss_rejected = 0, gnss_resets = 0;
  std::uint64_t imu_losses = 0;  ///< times the IMU fell silent while fixes kept coming (ImuLost())
  bool imu_lost = false;         ///< ImuLost() after the newest input
  std::uint64_t bad_input = 0;
  double last_nis_pos = 0, last_nis_vel = 0;
  double mean_nis_pos = 0;  ///< running mean of accepted position NIS (≈ 3 when consistent)
  std::uint64_t nis_count = 0;
  /// Innovation statistics of every aid source (InnovationMonitor)
  struct Aid {
    std::uint64_t accepted = 0, rejected = 0, windows_above = 0, windows_below = 0;
    double last_nis = 0, window_nis_per_dof = 0, band_low = 0, band_high = 0;
    int window_count = 0;
  } aid[kNumAidSources];
  double process_noise_scale = 1.0;  ///< the adapted scale of the IMU noise variances
  std::uint64_t fadings = 0;         ///< covariance fadings (all causes)
  std::uint64_t gap_fadings = 0;     ///< of which for a fix after a gap
  std::uint64_t reject_fadings = 0;  ///< of which for fixes rejected in a row
  std::uint64_t gap_recoveries = 0;  ///< gaps recovered from without the gate (gap_recovery_max)
  std::uint64_t recovery_fixes = 0;  ///< fixes fused without the gate in those recoveries
  std::uint64_t gnss_steps = 0;      ///< fixes that stepped where the INS did not (GnssStepCheck)
  std::uint64_t gnss_glitches = 0;   ///< receiver glitches (a rejected step) begun
  std::uint64_t gnss_glitch_rejected = 0;  ///< fixes rejected as part of a glitch
  bool stationary = false;                 ///< the vehicle stands (zero-velocity updates in use)
  double imu_tag_lag_s = 0;                ///< the lag taken off the IMU tags now (ImuTimeOffset)
  double imu_tag_lag_estimate_s = 0;       ///< the best lag on the evidence so far, and its σ
  double imu_tag_lag_std_s = 0;
  std::uint64_t stationary_periods = 0;
  /// the accelerometer's noise variances in use over the configured ones (1: as configured;
  /// above: the GNSS velocity shows the accelerometer that much noisier, ImuNoiseParams)
  double accel_noise_scale = 1.0;
  std::uint64_t accel_noise_raises = 0;  ///< windows that raised it
  /// the non-holonomic constraint's noise variances over the configured ones (NhcNoiseParams)
  double nhc_noise_scale = 1.0;
  std::uint64_t nhc_noise_raises = 0;      ///< windows that raised it
  std::uint64_t rtk_suspect_episodes = 0;  ///< RTK fix episodes judged a probable wrong fix
  std::uint64_t rtk_suspect_fixes = 0;     ///< fixes of those episodes, fused less their offset
  std::uint64_t rtk_frame_switches = 0;    ///< the filter moved to another frame (RtkFixFrames)
  std::uint64_t rtk_frame_episodes = 0;    ///< episodes seen in the filter's frame
  std::uint64_t rtk_other_frames = 0;      ///< other frames held as hypotheses now
  /// the IMU judged unusable (ImuUsabilityCheck): the solution is the vehicle-model fallback
  bool imu_unusable = false;
  double imu_consistency_stat = 0;       ///< Λ of the last test, χ²(dof) for a usable IMU
  double imu_consistency_threshold = 0;  ///< the Λ above which the IMU is unusable
  std::uint64_t imu_consistency_tests = 0, imu_unusable_periods = 0;
  /// the horizontal σ the last fix velocity was fused with (m/s; GnssVelocityNoise), 0: none yet
  double gnss_vel_std_mps = 0;
  bool gnss_vel_std_learned = false;  ///< that σ is the learned one, below the configured σ
  /// the IMU's mounting angles against the vehicle (ErrorStateEkf: pitch and yaw of the vehicle
  /// frame in the IMU frame, rad) and their σ, while they are estimated
  bool mount_estimated = false;
  double mount_pitch_rad = 0, mount_yaw_rad = 0, mount_pitch_std_rad = 0, mount_yaw_std_rad = 0;
  /// the z gyro's scale-factor error (ErrorStateEkf, kGyroScaleZ: fraction) and its σ, while it
  /// is estimated
  bool gyro_scale_z_estimated = false;
  double gyro_scale_z = 0, gyro_scale_z_std = 0;
  /// the x and y gyros' scale-factor errors (kGyroScaleX/Y: fraction) and their σ, while estimated
  bool gyro_scale_xy_estimated = false;
  Eigen::Vector2d gyro_scale_xy = Eigen::Vector2d::Zero();
  Eigen::Vector2d gyro_scale_xy_std = Eigen::Vector2d::Zero();
  /// the x and y gyros' coupling to the z rate (ErrorStateEkf, kGyroCouplingX/Y: rad) and their
  /// σ, while they are estimated
  /// the IMU tags' residual lag behind the fixes (ErrorStateEkf, kImuTimeResidual: s)
  double imu_time_residual_s = 0;
  bool gyro_z_coupling_estimated = false;
  Eigen::Vector2d gyro_z_coupling_rad = Eigen::Vector2d::Zero();
  Eigen::Vector2d gyro_z_coupling_std_rad = Eigen::Vector2d::Zero();
  /// the y accelerometer's scale error and the x and z accelerometers' coupling to the y specific
  /// force (ErrorStateEkf, kAccelScaleY, kAccelCouplingXY/ZY: fraction, rad) and their σ, while
  /// estimated
  bool accel_y_force_estimated = false;
  Eigen::Vector3d accel_y_force = Eigen::Vector3d::Zero();  ///< k_ay, m_xy, m_zy
  Eigen::Vector3d accel_y_force_std = Eigen::Vector3d::Zero();
};

/// The solution at one time of validity.
struct NavOutput {
  GpsTime t{};
  bool valid = false;
  Lla position;  ///< body reference point
  Eigen::Vector3d p_N_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_N_mps = Eigen::Vector3d::Zero();
  /// v_N_mps is known. False for a passed-through fix whose receiver gave no course (v_N_mps is
  /// then zero and means nothing; ground_speed_mps may still hold the reported speed).
  bool has_velocity = true;
  std::optional<double> ground_speed_mps;  ///< horizontal speed when known without a direction
  Eigen::Quaterniond q_NB = Eigen::Quaterniond::Identity();
  bool has_attitude = false;
  Eigen::Vector3d pos_std_enu_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_std_enu_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_std_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_B = Eigen::Vector3d::Zero(), gyro_bias_B = Eigen::Vector3d::Zero();
  std::uint32_t status = 0;
};

class Navigator {
 public:
  explicit Navigator(const NavigatorParams& params);

  void Push(const ImuSample& tagged);
  void Push(const GnssSample& g);
  void Push(const HeadingSample& h);
  /// Runs the filter up to the fusion horizon.
  void Update();
  /// Starts the EKF at a known state of the body origin at time t (a dataset's initial position,
  /// velocity and attitude) instead of aligning itself; the frame's origin is that position.
  void InitializeAt(GpsTime t, const Lla& body_position, const Eigen::Vector3d& v_N_mps,
                    const Eigen::Quaterniond& q_NB);
  /// Starts the EKF's bias estimates at known values (a dataset's initial biases; after
  /// InitializeAt).
  void SetImuBiases(const Eigen::Vector3d& accel_bias_B_mps2,
                    const Eigen::Vector3d& gyro_bias_B_radps) {
    ekf_.SetBiases(accel_bias_B_mps2, gyro_bias_B_radps);
  }
  /// Starts the gyros' scale-factor estimates at known values (x, y, z, fraction; after
  /// InitializeAt); those not estimated stay 0.
  void SetGyroScale(const Eigen::Vector3d& k) { ekf_.SetGyroScale(k); }
  /// The solution at the newest input time (IMU modes: output predictor).
  NavOutput Output() const;

  const EkfMatrix& covariance() const { return ekf_.covariance(); }
  const ErrorStateEkf& ekf() const { return ekf_; }
  std::uint32_t status() const { return status_; }
  const NavigatorStats& stats() const { return stats_; }
  bool aligned() const { return aligned_; }
  const LocalTangentFrame& frame() const { return frame_; }
  const NavigatorParams& params() const { return params_; }
  /// The newest IMU sample's time (its tag less the lag found, ImuTimeOffset): the time an
  /// Output() would have now.
  GpsTime newest_imu_time() const { return newest_imu_t_; }
  /// Filter (delayed) time.
  GpsTime filter_time() const { return filter_t_; }
  /// IMU modes: the IMU has been silent for imu_timeout of GNSS time while fixes arrive.
  bool ImuLost() const;

 private:
  void ProcessImu(const ImuSample& s);
  void ProcessGnss(const GnssSample& g);
  void SelectGnssErrorModel(const GnssSample& g);
  void TryAlign(const GnssSample& g);
  void EnsureFrame(const Lla& origin);
  void GnssOnlyFix(const GnssSample& g);
  void FallbackFix(const GnssSample& g);  ///< the solution while the IMU is lost
  /// GNSS position aid: the update, fading to it after a gap or a run of rejections, and the
  /// adaptation to its innovation window (aid_sources/gnss_position_control.cc).
  UpdateResult ControlGnssPosition(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m);
  /// The GNSS position gate's factor (RobustnessParams::gate_follows_median_nis), ≥ 1.
  double PositionGateScale() const;
  /// Starts a gap's recovery at a fix after a gap; whether `t` is in one (gap_recovery_max).
  bool InGapRecovery(GpsTime t, bool time_gap);
  void AdaptToInnovations();
  /// The GNSS consistency check before a fix's update: is this fix a step the INS did not make?
  bool CheckGnssStep(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m);
  /// A glitch is going on at t (begun, not yet over, not older than glitch_hold).
  bool InGnssGlitch(GpsTime t) const {
    return glitch_since_ && t - *glitch_since_ < params_.robust.glitch_hold;
  }
  /// Stationary detection before a prediction; zero-velocity and zero-angular-rate updates after
  /// it (aid_sources/zero_motion_control.cc).
  void DetectStationary(const ImuSample& s);
  /// The accelerometer's noise to the GNSS velocity innovation window (ImuNoiseParams).
  void AdaptAccelNoise();
  /// The non-holonomic constraint's noise to its innovation window (NhcNoiseParams).
  void AdaptNhcNoise();
  /// The IMU tag lag: a sample's heading increment into the estimate, and its tag corrected by
  /// the lag found so far; a fix's course into the estimate (aid_sources/imu_lag_control.cc).
  void CorrectImuTag(ImuSample& s);
  void ObserveGnssCourse(const GnssSample& g);
  void ControlZeroMotion();
  /// Wrong RTK fixes before a fix's update (aid_sources/rtk_fix_control.cc): an episode's first
  /// fix judged against the filter's and the other frames (RtkFixFrames; the filter moved when
  /// another frame wins); a fix of a suspect episode fused less its frame's offset, returned as
  /// rejected (its velocity is fused by FuseGnssVelocity all the same). nullopt: fuse it as usual.
  std::optional<UpdateResult> ControlRtkFix(const GnssSample& g,
                                            const Eigen::Vector3d& p_antenna_N_m);
  UpdateResult FuseSuspectRtkFix(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m);
  /// An episode's first fix (or a suspect episode's fix after its offset changed) into
  /// RtkFixFrames: the filter moved, or the episode suspect, as it decides.
  void JudgeRtkEpisode(const GnssSample& g, const PositionInnovation& first_fix);
  static UpdateResult RejectedFix();
  /// fixes of a suspect episode in a row out of its frame that make it a new episode
  static constexpr int kRtkOffFrameFixes = 3;
  void MoveToRtkFrame(const RtkFixFrames::Decision& d);
  void RecordRtkFrames();
  /// The fix's velocity (when it has one and use_gnss_velocity), recorded in its monitor.
  void FuseGnssVelocity(const GnssSample& g);
  void Record(int source, const UpdateResult& r);
  /// Copies the EKF's mounting-angle estimate into stats_ (aid_sources/mount_angle_control.cc).
  void RecordMountAngles();
  /// Copies the EKF's z-gyro scale estimate into stats_ (aid_sources/gyro_scale_record.cc).
  void RecordGyroScale();
  /// Restarts the EKF's position and velocity at a fix (long rejection, or after an IMU loss).
  void ResetToFix(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m);
  bool UsesImu() const { return estimator::UsesImu(params_.mode); }
  bool FallsBackToFixes() const;  ///< modes whose solution becomes the fix when the IMU is lost
  void MultiGnssFix(const GnssSample& g);
  /// Is the IMU usable (ImuUsabilityCheck)? Its samples and the fixes into the test, the fixes
  /// into the vehicle-model fallback (aid_sources/imu_usability_control.cc).
  void ObserveImuUsability(const ImuSample& s);
  void ControlImuUsability(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m);
  bool UsesVehicleModel() const { return imu_check_.unusable() && fallback_.ready(); }
  NavOutput VehicleModelOutput() const;

  NavigatorParams params_;
  ErrorStateEkf ekf_;
  PlanarFilter planar_;
  LocalTangentFrame frame_;
  bool frame_set_ = false;
  bool aligned_ = false;
  RingBuffer<ImuSample, 1024> imu_;  // 10 s at 100 Hz: covers the longest GNSS wait
  RingBuffer<GnssSample, 32> gnss_;
  std::optional<HeadingSample> heading_;
  GpsTime newest_imu_t_{}, filter_t_{}, last_gnss_fused_t_{}, last_nhc_t_{};
  std::optional<GpsTime> first_rejected_t_;  // first of the current run of rejected fixes
  double height_datum_var_m2_ = 0.0;         // the last fix's height_datum_std_m²
  bool gnss_float_ = false;           // the correlated GNSS error model in use is the RTK float one
  bool restart_at_next_fix_ = false;  // IMU samples resumed after a loss
  int fixes_since_imu_ = 0;           // fixes pushed since the last IMU sample
  std::optional<GpsTime> newest_gnss_t_;  // GNSS stream timing (for the wait)
  Nanoseconds gnss_period_{0};
  bool have_imu_ = false;
  Eigen::Vector3d mean_f_B_ = Eigen::Vector3d::Zero();
  double mean_f_weight_ = 0;
  std::uint32_t status_ = 0;
  NavigatorStats stats_;
  InnovationMonitor monitors_[kNumAidSources];
  int nhc_far_updates_ = 0;  // NHC updates in a row with their window far above its band
  StationaryDetector stationary_;
  VibrationVelocity vibration_;  // the IMU's vibration velocity (vibration_tau_s)
  AccelScatter accel_scatter_;   // the accelerometer's noise from its own scatter
  bool stationary_now_ = false;
  GpsTime last_zupt_t_{};
  std::optional<GpsTime> last_fix_seen_t_;  // the newest fix the filter processed
  std::optional<GpsTime> recovery_until_;   // recovering from a gap until then (gap_recovery_max)
  int recovery_passes_ = 0;                 // fixes in a row in it that the gate would have taken
  GnssStepCheck step_;                      // GNSS increments against the INS displacement
  ImuTimeOffset imu_lag_;                   // the IMU tags' lag behind GNSS time
  Nanoseconds imu_lag_applied_{0};          // the lag taken off the IMU tags now
  Nanoseconds gyro_states_lag_{0};          // the lag applied when the gyro triad's states started
  std::optional<GpsTime> glitch_since_;     // the current receiver glitch's first fix
  RtkFixCheck rtk_check_;                   // wrong RTK fixes: fix episodes, the suspect one
  RtkFixFrames rtk_frames_;                 // the filter's frame of episodes and the others
  int rtk_off_frame_fixes_ = 0;             // the suspect episode's fixes in a row out of its frame
  ImuUsabilityCheck imu_check_;             // is the IMU usable at all?
  VehicleModelFilter fallback_;             // GNSS + vehicle model, the solution when it is not
  GnssVelocityNoise vel_noise_;             // the fix velocity's σ from its increments
  // the last fix velocity (GnssVelocityNoise): its time, value and lever-arm term, and the INS's
  // own velocity increment since
  std::optional<GpsTime> last_vel_fix_t_;
  Eigen::Vector3d last_vel_fix_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_vel_lever_N_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d ins_dv_N_mps_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector2d> last_vel_d_;  // the previous increment (its lag-1 correlation)
  FixVelocityRipple fix_ripple_;               // the INS's ripple as the fix velocities see it
  std::optional<GpsTime> last_gnss_vel_t_;     // the newest fix with a velocity, and its speed
  double last_gnss_speed_mps_ = 0;
  // GNSS-only and multi-receiver modes: the last fix
  NavOutput direct_;
  // multi-receiver mode: each receiver's fixes not yet combined (receivers' streams may arrive in
  // bursts of many epochs, one receiver after the other)
  RingBuffer<GnssSample, 64> multi_[kMaxGnssAntennas];
};

}  // namespace hil::estimator

#pragma once
/// @file
/// @system
/// name: TruthIntegrator (ground-truth vehicle motion, SUNDIALS CVODE)
/// input: TruthConfig (origin, vehicle, path and guidance, terrain, vibration) — constant for a run
/// output: TruthSample at any requested time, from CVODE's dense output (CVodeGetDky)
/// @endsystem
///
/// **Continuous state** (integrated by CVODE, Adams–Moulton with the fixed-point nonlinear solver,
/// non-stiff, free one-step mode): y = [e, n, ψ, v, u] with u = δ (steering angle, bicycle
/// models) or ω (yaw rate, differential drive); the equations are in vehicle.h. The 3-D motion
/// (terrain, vibration) is a closed-form function of y, its derivatives and t (body_motion.h), so
/// position, velocity, acceleration, attitude, angular rate and specific force are consistent by
/// construction.
///
/// **Guidance** (pure pursuit along the planned path, on truth, open loop w.r.t. the estimator) is
/// a discrete controller: it computes the commands (v_cmd, δ_cmd or ω_cmd) at a fixed rate
/// (GuidanceConfig::rate_hz, 50 Hz by default) and holds them in between. The lags of v and u
/// (speed, steering or yaw-rate lag, vehicle.h) are not integrated: under held commands each has
/// a closed form (actuator_lag.h) from its value at the last update, and CVODE integrates
/// y = [e, n, ψ] only. An update moves only the lags' targets: v and u do not jump, so the
/// right-hand side of y stays continuous (its derivative has a kink) and CVODE goes on without a
/// restart, its error control taking the kink (seed004's 1800 s: positions within 6 µm of an
/// rtol 10⁻¹² solution, as with a re-initialisation at each of its 50 Hz updates, which took
/// 20 % of the run's time). This was chosen over continuous guidance inside the RHS because pure
/// pursuit on a polyline is only piecewise smooth in the state (its look-ahead point jumps between
/// segments), because real guidance controllers are discrete, and because the per-update cost is
/// bounded and measured (truth_bench).
///
/// **Events** by root finding (CVodeRootInit), each a restart (CVodeReInit): passing each path
/// vertex (the bisector of the two segments, or the perpendicular at a stop vertex) switches the
/// active segment, starts a stop, a turn in place (differential drive, sharp corners) or ends the
/// path. Time events (guidance updates, the end of a stop, steps of a speed profile) use the stop
/// time.
///
/// **Commands as inputs (closed loop)**: with `TruthConfig::external_commands` the built-in
/// guidance is off and the vehicle obeys the commands given by `SetCommand` (speed and steering
/// angle or yaw rate, the outputs of the emulated actuators), piecewise constant on a grid of
/// `command_period_s`: a command set for time t takes effect at the first grid instant ≥ t. The
/// integrator stops at every grid instant (CVodeSetStopTime) where the command changes, and goes
/// on without a restart, as under guidance updates. Commands must be set before the truth is
/// sampled past their grid instant (the lockstep guarantees it); a late command is still
/// honoured, by re-integrating from t = 0 with the whole command history (deterministic, slower).
/// A `path`, if given, is then used for the samples' cross-track only. With `command_hold_s` the
/// truth ramps linearly to each command over that time (the closed loop's setting: the emulated
/// actuator is the one model; a step held through a 1 ms lag instead put a spike of 10× the
/// actuator's acceleration into every IMU sample taken just after a command, so a 0.5 m/s stop
/// at 3 m/s² read as a 4.7 m/s change of velocity).
///
/// **Sampling**: requests must come in non-decreasing time order; each is read from the
/// interpolating polynomial of the last step (CVodeGetDky), so the step sequence does not depend
/// on which sensors sample the truth. Commands are right-continuous: a sample exactly at a
/// guidance update sees the new commands. A request before the dense-output window of the last
/// step restarts the integration from t = 0 (deterministically: the same sample results).

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "hil/firmware_emu/truth_sample.h"
#include "hil/truth/local_frame.h"
#include "hil/truth/path.h"
#include "hil/truth/terrain.h"
#include "hil/truth/vehicle.h"

namespace hil::truth {

/// The pure-pursuit path follower and its speed logic.
struct GuidanceConfig {
  double lookahead_m = 2.0;       ///< pure-pursuit look-ahead distance along the path
  double rate_hz = 50;            ///< guidance update rate
  double stop_decel_mps2 = 0.3;   ///< speed limit before a stop: √(2·a·distance)
  double creep_speed_mps = 0.05;  ///< lowest commanded speed while approaching a stop
  /// diff_drive: vertices where the path turns by more than this are taken by stopping and
  /// turning in place to the next segment's heading.
  double turn_in_place_deg = 30;
  double turn_in_place_done_deg = 1;   ///< heading error that ends a turn in place
  double turn_heading_gain_per_s = 2;  ///< ω_cmd = gain · heading error (saturated) while turning
};

/// A step of the nominal speed: from `t_s` on, the vehicle is commanded to `speed_mps`.
struct SpeedStep {
  double t_s = 0;
  double speed_mps = 0;
};

/// What the truth integrator needs to know; constant for a run.
struct TruthConfig {
  Geodetic origin;  ///< scenario origin (ENU frame origin)
  VehicleParams vehicle;
  /// The planned path, followed by pure pursuit. Without one the vehicle drives open loop from
  /// the start point at `heading_deg` with the constant steering angle `steer_deg` (a line, or a
  /// circle of radius L / tan δ) or, for diff_drive, the constant yaw rate `yaw_rate_dps` (with
  /// zero speed: turning in place).
  std::optional<Path> path;
  GuidanceConfig guidance;
  /// Start point (ENU, m); default: the origin, or the path's first vertex.
  std::optional<Eigen::Vector2d> start_p_N_m;
  /// Initial heading, degrees clockwise from north; default 0, or the first segment's direction.
  std::optional<double> heading_deg;
  double speed_mps = 0.4444444444444444;  ///< nominal commanded forward speed
  std::vector<SpeedStep> speed_profile;   ///< if given, replaces speed_mps from each step's time on
  double steer_deg = 0;     ///< open loop, bicycle: constant front-wheel angle, left positive
  double yaw_rate_dps = 0;  ///< open loop, diff_drive: constant commanded yaw rate, left positive
  bool start_at_speed = true;  ///< start moving at the commanded speed
  TerrainConfig terrain;
  VibrationConfig vibration;
  bool earth_rotation =
      true;             ///< include Earth rate in the gyro truth and Coriolis in the specific force
  double rtol = 1e-10;  ///< CVODE relative tolerance
  double atol_m = 1e-9;     ///< CVODE absolute tolerance on positions (m); angles get atol_m/10 rad
  double max_step_s = 0.5;  ///< CVODE maximum step
  /// Closed loop: commands come from `TruthIntegrator::SetCommand`, not from the built-in guidance.
  bool external_commands = false;
  double command_period_s = 0.01;  ///< grid on which external commands take effect
  /// Closed loop: how the truth reconstructs the actuators' sampled output between grid instants.
  /// > 0: a first-order hold, the speed and the steering input ramp linearly from their values to
  /// each new command over this time (the command period: continuous, with the actuator's mean
  /// rate of change as its derivative; the vehicle's own lags, `speed_lag_s` …, are then unused,
  /// the emulated actuator being the one model of the command path). 0: the vehicle's lags.
  double command_hold_s = 0;
};

class TruthIntegrator {
 public:
  /// @throws std::invalid_argument for an inconsistent configuration.
  explicit TruthIntegrator(const TruthConfig& config);
  ~TruthIntegrator();
  TruthIntegrator(const TruthIntegrator&) = delete;
  TruthIntegrator& operator=(const TruthIntegrator&) = delete;

  /// The truth at time t (see the file comment for ordering).
  /// @throws std::runtime_error if CVODE fails (names the CVODE call and flag).
  TruthSample Sample(Time t);
  const LocalFrame& frame() const { return frame_; }
  const Terrain& terrain() const { return terrain_; }
  const TruthConfig& config() const { return config_; }
  /// Closed loop (`external_commands`): from the first grid instant ≥ t on, the commanded forward
  /// speed is `speed_mps` and the steering command `steer_or_yaw_rate` (front-wheel angle in rad,
  /// left positive, for the bicycle models; yaw rate in rad/s, left positive, for diff_drive).
  /// Times must not decrease from one call to the next.
  /// @throws std::logic_error without `external_commands`, std::invalid_argument for a decreasing
  /// time.
  void SetCommand(Time t, double speed_mps, double steer_or_yaw_rate);
  /// Commands given so far, and re-integrations from t = 0 forced by late commands.
  long commands() const;
  long late_command_restarts() const;
  /// A command set since the last sample acts at or before that sample's instant (a late one, or
  /// the first at t = 0): the samples taken so far do not all hold for the commands as they now
  /// are, and the next Sample re-integrates from t = 0.
  bool restart_pending() const;
  /// CVODE internal steps taken so far, over all re-initialisations (for benchmarks).
  long steps() const;
  /// Re-initialisations (input discontinuities) so far.
  long reinits() const;
  /// Root-finding events (vertex passages) so far.
  long root_events() const;

 private:
  struct Impl;
  TruthConfig config_;
  LocalFrame frame_;
  Terrain terrain_;
  std::unique_ptr<Impl> impl_;
};

/// Normal gravity (WGS-84, gravitation plus centrifugal) at an ENU point, expressed in N (m/s²).
Eigen::Vector3d GravityAt(const LocalFrame& frame, const Eigen::Vector3d& p_N_m);
/// Earth's rotation rate relative to inertial space, expressed in N (rad/s).
Eigen::Vector3d EarthRateIn(const LocalFrame& frame);

}  // namespace hil::truth

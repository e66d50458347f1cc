#pragma once
/// @file
/// @system
/// name: TruthIntegrator (ground-truth vehicle motion, SUNDIALS CVODE)
/// input: TruthConfig (vehicle, path, origin) — constant for a run
/// output: TruthSample at any requested time, from CVODE's dense output (CVodeGetDky)
/// @endsystem
///
/// The continuous state is integrated with CVODE (Adams–Moulton with the fixed-point nonlinear
/// solver, non-stiff) in free one-step mode; samples at exact sensor times are read from the
/// interpolating polynomial, so the step sequence does not depend on which sensors sample it.
/// Requests must come in non-decreasing time order; a request before the last one restarts the
/// integration from t = 0 (deterministically).
///
/// Kinematic bicycle model on flat ground, reference point at the rear axle:
///   ė = v cos ψ,  ṅ = v sin ψ,  ψ̇ = v tan δ / L,  v̇ = (v_cmd − v) / τ_v
/// with ψ the yaw of the body x axis counter-clockwise from east.

#include <memory>

#include "hil/firmware_emu/truth_sample.h"
#include "hil/truth/local_frame.h"

namespace hil::truth {

/// What the truth integrator needs to know; constant for a run.
struct TruthConfig {
  Geodetic origin;                        ///< scenario origin (ENU frame origin)
  Eigen::Vector2d start_p_N_m{0, 0};      ///< start point in ENU (m)
  double heading_deg = 0;                 ///< initial course, degrees clockwise from north
  double speed_mps = 0.4444444444444444;  ///< commanded forward speed
  double steer_deg = 0;                   ///< constant front-wheel steering angle, left positive
  double wheelbase_m = 0.84;
  double speed_lag_s = 0.5;               ///< first-order speed actuator lag
  bool start_at_speed = true;             ///< start moving at the commanded speed
  bool earth_rotation = true;             ///< include Earth rate in the gyro truth (w_IB_B)
  double rtol = 1e-10;                    ///< CVODE relative tolerance
  double atol_m = 1e-9;                   ///< CVODE absolute tolerance
};

class TruthIntegrator {
 public:
  explicit TruthIntegrator(const TruthConfig& config);
  ~TruthIntegrator();
  TruthIntegrator(const TruthIntegrator&) = delete;
  TruthIntegrator& operator=(const TruthIntegrator&) = delete;

  /// The truth at time t (see the class comment for ordering).
  /// @throws std::runtime_error if CVODE fails (names the CVODE flag).
  TruthSample Sample(Time t);
  const LocalFrame& frame() const { return frame_; }
  /// CVODE internal steps taken so far (for benchmarks).
  long steps() const;

 private:
  struct Impl;
  TruthConfig config_;
  LocalFrame frame_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hil::truth

#pragma once
/// @file
/// @system
/// name: ImuFrontEnd (the analog side of an IMU chip, between the board's motion and its ADC
/// output) input: the ideal specific force and angular rate at each output sample instant (IMU
/// frame I) output: the band-limited specific force and angular rate at that instant, before the
/// sensor's
///         errors (scale, bias, noise) and quantisation
/// rate: an internal loop at RoughImuSpec::internal_rate_hz between two output samples
/// @endsystem
/// Between two samples the rigid-body motion is interpolated linearly; the vibration
/// (VibrationSource) is added; the sum is clipped at the sensor's range (the ADC's full scale, so
/// vibration beyond it rectifies into a bias) and filtered by a second-order Butterworth
/// anti-alias low-pass; the output sample is the filter's value at the sample instant. When that
/// low-pass is wider than half the output rate, vibration aliases into the output band. The
/// vibration's angular rate turns the sensor: the angle it integrates to (θ, small) tilts the
/// rigid body's specific force into the sensor frame (f − θ × f), so that the accelerometer sees
/// the gravity a roll or pitch oscillation tilts into it, as a rigid board would. Without it the
/// gyro reported a rotation the accelerometer did not (the ride's 1.5–1.9 Hz roll mode: 2 mrad,
/// 0.02 m/s² of gravity missing at the accelerometer). θ leaks with a 10 s time constant (chosen:
/// far below the ride's lowest band, 0.5–1 Hz, so the oscillation is kept, and it holds any
/// numerical drift of the integral at bay; an engine order's sine integrates to a constant
/// offset otherwise).

#include <cstdint>

#include <Eigen/Core>

#include "hil/firmware_emu/mcu/biquad3.h"
#include "hil/firmware_emu/mcu/rough_imu_spec.h"
#include "hil/firmware_emu/mcu/vibration_source.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::mcu {

/// The front end's fixed parameters besides RoughImuSpec.
struct FrontEndLimits {
  double accel_range_mps2 = 1e300;
  double gyro_range_radps = 1e300;
  double accel_aaf_hz = 0;  ///< second-order Butterworth cutoff (must be < internal_rate/2)
  double gyro_aaf_hz = 0;
};

class ImuFrontEnd {
 public:
  /// @throws std::invalid_argument on a cutoff at or above half the internal rate.
  ImuFrontEnd(const RoughImuSpec& spec, const FrontEndLimits& limits, std::uint64_t seed);

  /// Runs the internal loop from the previous sample up to `t` and returns the band-limited values
  /// at `t`. The first call settles the filters on its input (no start-up transient).
  void Advance(Time t, const Eigen::Vector3d& f_I_mps2, const Eigen::Vector3d& w_I_radps,
               Eigen::Vector3d& f_out, Eigen::Vector3d& w_out);
  /// The vehicle's forward speed for the next Advance (the ride scales with it; see
  /// RoughImuSpec::ride_reference_speed_mps).
  void SetGroundSpeed(double speed_mps) { vibration_.SetGroundSpeed(speed_mps); }

 private:
  RoughImuSpec spec_;
  FrontEndLimits limits_;
  VibrationSource vibration_;
  Biquad3 accel_aaf_, gyro_aaf_;
  bool first_ = true;
  Time t_prev_{};
  Eigen::Vector3d f_prev_ = Eigen::Vector3d::Zero(), w_prev_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_last_ = Eigen::Vector3d::Zero(), w_last_ = Eigen::Vector3d::Zero();
  static constexpr double kVibrationTiltLeakTau_s = 10.0;    ///< θ's leak (class comment)
  Eigen::Vector3d vib_angle_rad_ = Eigen::Vector3d::Zero();  ///< the vibration's angle θ
};

}  // namespace hil::mcu

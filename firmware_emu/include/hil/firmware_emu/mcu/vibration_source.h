#pragma once
/// @file
/// @system
/// name: VibrationSource (what the IMU board feels from the engine and the ground)
/// input: the crank speed (RPM) of each interval; the internal time step
/// output: vibration specific force (m/s²) and angular rate (rad/s) in the IMU frame I, per step
/// rate: the front end's internal rate (RoughImuSpec::internal_rate_hz)
/// @endsystem
/// Engine orders are phasors rotated by order × crank angle (phases per axis drawn from the seed);
/// ride vibration is white noise of the band's PSD through Butterworth high- and low-pass
/// sections, generated at a sub-rate of at least 16 × its highest band edge and interpolated
/// linearly onto the internal steps (ride vibration lies far below the internal rate; this keeps
/// the model's cost within issue 41's budget); both then pass the mount's transmissibility. Every
/// draw comes from the seed.

#include <complex>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/mcu/biquad3.h"
#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/mcu/rough_imu_spec.h"

namespace hil::mcu {

class VibrationSource {
 public:
  /// @throws std::invalid_argument when a band or the mount does not fit below internal_rate/2.
  VibrationSource(const RoughImuSpec& spec, std::uint64_t seed);

  /// Sets the crank speed and the step for the following steps (held until the next call); the
  /// order phasors are recomputed exactly from the crank angle here, and rotated per step.
  void SetRpm(double rpm, double dt_s);
  /// Sets the vehicle's forward speed for the following steps: the ride's PSD scales with
  /// |speed| / RoughImuSpec::ride_reference_speed_mps (when that is > 0).
  void SetGroundSpeed(double speed_mps);
  /// Advances by one step and returns the vibration at its end.
  void Step(Eigen::Vector3d& f_I_mps2, Eigen::Vector3d& w_I_radps);
  /// Crank angle travelled so far, rad.
  double crank_angle_rad() const { return crank_rad_; }

 private:
  struct Order {
    double order;
    std::complex<double> phasor, rotation;  ///< e^{j·order·crank}, its change per step
    Eigen::Vector3d accel_re, accel_im, gyro_re, gyro_im;  ///< amplitude · e^{jφ} per axis
  };
  struct Band {
    Eigen::Vector3d accel_sigma, gyro_sigma;  ///< per-step std of the white drive
    Biquad3 accel_hp, accel_lp, gyro_hp, gyro_lp;
  };
  double UniformUnitVariance();
  void NextRideSample();

  Rng rng_;
  double crank_rad_ = 0;
  double crank_radps_ = 0;
  double dt_s_ = 0;
  std::vector<Order> orders_;
  std::vector<Band> bands_;
  int ride_decimation_ = 1;  ///< internal steps per ride sample
  double ride_reference_speed_mps_ = 0;
  double ride_drive_scale_ = 1;  ///< √(|v| / v_ref): the white drive's factor at this speed
  int ride_phase_ = 0;
  Eigen::Vector3d ride_f_prev_ = Eigen::Vector3d::Zero(), ride_f_next_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d ride_w_prev_ = Eigen::Vector3d::Zero(), ride_w_next_ = Eigen::Vector3d::Zero();
  bool mount_enabled_ = false;
  Biquad3 accel_mount_, gyro_mount_;
};

}  // namespace hil::mcu

#pragma once
/// @file
/// Configuration of the field-rough IMU model (issue 41): what the board feels besides the
/// vehicle's rigid-body motion (engine orders from an RPM profile, broadband ride vibration from a
/// PSD, a mount resonance), the sensor's own front end (ADC clipping at its range and a
/// second-order anti-alias low-pass, run at an internal rate well above the output rate so that
/// vibration aliases as on a real board), the temperature profile, and the sample's time tag
/// (latency, jitter, IMU oscillator drift against the MCU). The sensor error terms themselves
/// (noise, bias instability, scale, misalignment, g-sensitivity …) live in TriadErrorSpec
/// (sensor_spec.h). Every member defaults to "off": a scenario without the new keys runs the
/// previous model, byte for byte. Named field profiles (field_profiles.h) fill this from data
/// sheets and papers.
///
/// Frames: amplitudes are in the IMU case frame I (x, y, z of the board).

#include <vector>

#include <Eigen/Core>

namespace hil::mcu {

/// One point of a piecewise-linear profile (RPM or temperature) over scenario time.
struct ProfilePoint {
  double t_s = 0;
  double value = 0;
};

/// Linear interpolation in a profile sorted by time; held constant outside it. Empty → fallback.
double InterpolateProfile(const std::vector<ProfilePoint>& profile, double t_s, double fallback);

/// One engine order: a sinusoid at `order` × the crank rotation frequency (RPM / 60). A four-stroke
/// engine of n cylinders fires at order n/2, a single-cylinder two-stroke at order 1.
struct EngineOrder {
  double order = 1;
  Eigen::Vector3d accel_amplitude_mps2 = Eigen::Vector3d::Zero();  ///< peak, per axis
  Eigen::Vector3d gyro_amplitude_radps = Eigen::Vector3d::Zero();  ///< peak, per axis
};

/// One band of broadband ride vibration: a flat one-sided PSD between the band edges, with
/// second-order Butterworth skirts (white noise high-passed at f_low and low-passed at f_high).
struct RideBand {
  double f_low_hz = 1;
  double f_high_hz = 20;
  Eigen::Vector3d accel_psd_mps2_sq_per_hz = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_psd_radps_sq_per_hz = Eigen::Vector3d::Zero();
};

/// The board's mount as a base-excited single-degree-of-freedom oscillator: transmissibility
/// (2ζωn s + ωn²)/(s² + 2ζωn s + ωn²), unity at low frequency, 1/(2ζ) at fn, falling above.
/// It shapes the engine and ride vibration (not the vehicle's rigid-body motion).
struct MountResonance {
  double frequency_hz = 0;  ///< 0: rigid mount (no resonance)
  double damping_ratio = 0.1;
};

/// The sample's time tag: the MCU tags a sample later than the instant it measured.
struct TimeTagSpec {
  double latency_s = 0;      ///< constant: sense instant → tagged (read) instant
  double jitter_s = 0;       ///< extra tag delay, uniform in [0, jitter_s], per sample
  double imu_clock_ppm = 0;  ///< the IMU's own output-rate oscillator, against nominal
  bool enabled() const { return latency_s > 0 || jitter_s > 0 || imu_clock_ppm != 0; }
};

struct RoughImuSpec {
  /// Rate of the front end's internal loop (vibration, clipping, anti-alias filter), Hz. 0 = the
  /// vibration front end is off (the previous model). Must be ≥ 4 × the IMU output rate.
  double internal_rate_hz = 0;
  /// Second-order Butterworth anti-alias low-pass of each triad, Hz (0: the triad's bandwidth_hz).
  double accel_aaf_hz = 0;
  double gyro_aaf_hz = 0;
  std::vector<ProfilePoint> rpm_profile;  ///< crank speed, RPM
  std::vector<EngineOrder> engine_orders;
  std::vector<RideBand> ride;
  /// Forward speed at which the ride bands' PSDs hold, m/s. The ride comes from the ground: a
  /// terrain whose elevation PSD falls as the spatial frequency n^-2 (ISO 8608's road/terrain
  /// classes, waviness w = 2) excites a vehicle at speed v with a temporal acceleration PSD
  /// ∝ v at every frequency, so each band's PSD is scaled by |v| / this speed (its r.m.s. by the
  /// square root) and a standing vehicle has no ride. 0: the PSDs hold at any speed.
  double ride_reference_speed_mps = 0;
  MountResonance mount;
  std::vector<ProfilePoint> temperature_profile;  ///< board temperature, °C (replaces the ramp)
  TimeTagSpec time_tag;
  bool front_end_enabled() const { return internal_rate_hz > 0; }
};

}  // namespace hil::mcu

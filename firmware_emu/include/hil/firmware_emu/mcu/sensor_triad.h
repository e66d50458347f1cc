#pragma once
/// @file
/// @system
/// name: SensorTriad (one three-axis sensor of the IMU board: accelerometer, gyro or compass)
/// input: the true physical value in the IMU frame I at each sample instant, the temperature
/// output: the integer counts the firmware puts into its frames (output LSB = counts.output_lsb())
/// rate: called once per sample; the sample period is fixed at construction
/// @endsystem
/// Per axis: scale factor and misalignment (drawn at power-on), turn-on bias, Gauss–Markov bias
/// instability, bias random walk, temperature drift, white noise (per the sampling mode), a
/// first-order low-pass before sampling, vibration tones, saturation and quantisation (with ADC
/// oversampling for analog sensors). Every random draw comes from the seeds given.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/mcu/sensor_spec.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::mcu {

/// One sample in counts.
struct TriadCounts {
  std::array<std::int16_t, 3> counts{};  ///< output LSBs per axis
  std::array<bool, 3> saturated{};       ///< the axis hit its range or register limit
};

class SensorTriad {
 public:
  /// @param sample_period_s nominal time between samples (> 0)
  /// @param seed seeds every draw of this triad (power-on errors and noise)
  SensorTriad(const TriadSpec& spec, double sample_period_s, std::uint64_t seed);

  /// Adds vibration tones (phases drawn from the triad's seed); `accel` selects which amplitude
  /// of each tone applies (accelerometer or gyro).
  void SetVibration(const std::vector<VibrationTone>& tones, bool accel);

  /// The erroneous continuous value (engineering units) of the sample at `t` for true input
  /// `true_I`: everything except quantisation. Advances the random processes by one sample.
  Eigen::Vector3d Measure(const Eigen::Vector3d& true_I, Time t, double temperature_c);
  /// The rough-model path (issue 41): the erroneous continuous value of the sample whose
  /// band-limited physical input (after the front end's clipping and anti-alias filter, vibration
  /// included) is `band_limited_I`; `extra_I` is added before the scale factor (the gyro's
  /// g-sensitivity term). Applies scale (with its temperature term), misalignment, turn-on bias,
  /// bias instability, rate random walk, temperature bias and white noise. Advances one sample.
  Eigen::Vector3d MeasureBandLimited(const Eigen::Vector3d& band_limited_I,
                                     const Eigen::Vector3d& extra_I, double temperature_c);
  /// Quantises a continuous value into counts (ADC path, oversampling, saturation).
  TriadCounts Quantise(const Eigen::Vector3d& value);
  /// Measure then Quantise.
  TriadCounts Sample(const Eigen::Vector3d& true_I, Time t, double temperature_c) {
    return Quantise(Measure(true_I, t, temperature_c));
  }

  /// Engineering units per output LSB.
  double output_lsb() const { return spec_.counts.output_lsb(); }
  const TriadSpec& spec() const { return spec_; }
  /// Power-on errors actually drawn (for tests and reports).
  const Eigen::Vector3d& turn_on_bias() const { return turn_on_bias_; }
  const Eigen::Matrix3d& scale_misalignment() const { return scale_misalignment_; }

 private:
  struct Tone {
    double omega_radps;
    Eigen::Vector3d amplitude;
    Eigen::Vector3d phase_rad;
  };
  Eigen::Vector3d VibrationAt(double t_s) const;
  void InitFlicker(std::uint64_t seed);
  void AdvanceBiases();

  TriadSpec spec_;
  double period_s_;
  Rng rng_;
  Eigen::Matrix3d scale_misalignment_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d turn_on_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gm_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d rw_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d filtered_ = Eigen::Vector3d::Zero();
  bool first_ = true;
  double gm_phi_ = 0, gm_drive_ = 0, white_sigma_scale_ = 0;
  std::vector<Tone> tones_;
  // flicker: a sum of Gauss–Markov processes (flicker_terms > 0), drawn from their own stream
  Rng flicker_rng_{0};
  std::vector<double> flicker_phi_, flicker_drive_;
  std::vector<Eigen::Vector3d> flicker_state_;
};

/// Allan variance of a first-order Gauss–Markov process of variance σ² = 1 and correlation time
/// tau_c_s at averaging time tau_s.
double GaussMarkovAllanVariance(double tau_s, double tau_c_s);

}  // namespace hil::mcu

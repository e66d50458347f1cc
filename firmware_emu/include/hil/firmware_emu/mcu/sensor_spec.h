#pragma once
/// @file
/// Configuration of the IMU board's sensors: the error model of each sensor triad (accelerometer,
/// gyroscope, magnetometer), the path from the physical value to the counts the firmware reads
/// (ADC or digital register), and the named profiles (the seed-000 Razor v13 board and the
/// consumer / industrial / tactical grades of estimators.md §6). Immutable after construction.
///
/// Units: every "engineering unit" below is SI per triad — m/s² (accelerometer), rad/s (gyro),
/// µT (magnetometer). Densities are per √Hz, random walks per √s.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::mcu {

/// How the firmware turns the sensor's continuous output into one sample.
enum class Sampling {
  /// The sample is the mean of the sensor output over the sample period (oversampling); white
  /// noise per sample is noise_density / √T, so an Allan deviation recovers the density.
  kAverage,
  /// The sample is the sensor's (band-limited) output at the sample instant; white noise per
  /// sample is noise_density · √(π/2 · bandwidth): noise above the Nyquist rate aliases.
  kPoint,
};

/// Errors of one three-axis sensor, identical in law for the three axes (drawn independently).
struct TriadErrorSpec {
  Eigen::Vector3d noise_density = Eigen::Vector3d::Zero();  ///< white noise per axis, unit/√Hz
  /// Bias instability B: the flat floor of the Allan deviation is B·√(2 ln2 / π) ≈ 0.664 B.
  /// Modelled as a first-order Gauss–Markov bias whose Allan deviation peaks at 0.664 B.
  double bias_instability = 0;
  double bias_correlation_time_s = 100;  ///< Gauss–Markov correlation time τc (peak at 1.89 τc)
  double bias_random_walk = 0;           ///< rate random walk K, unit/√s
  Eigen::Vector3d turn_on_bias_sigma = Eigen::Vector3d::Zero();  ///< per power-on, unit (1σ)
  double scale_factor_sigma_ppm = 0;  ///< per-axis scale factor error (1σ)
  double misalignment_sigma_rad = 0;  ///< each off-diagonal axis coupling (1σ, non-orthogonal)
  double bandwidth_hz = 0;            ///< first-order low-pass before sampling; 0 = none
  double bias_temperature_coeff_per_c = 0;  ///< bias change per °C away from 25 °C, unit/°C
  // ---- issue 41 terms (all off by default: the previous model, byte for byte) ----
  /// When > 0, the bias instability B is a sum of this many first-order Gauss–Markov processes of
  /// one σ with correlation times log-spaced over [flicker_tau_min_s, flicker_tau_max_s] (a flat
  /// flicker floor 0.664 B over that band) instead of the single process above.
  int flicker_terms = 0;
  double flicker_tau_min_s = 1;
  double flicker_tau_max_s = 1000;
  double scale_temperature_ppm_per_c = 0;  ///< scale factor change per °C away from 25 °C
  /// Gyro only: rate error per m/s² of specific force on the same axis (g-sensitivity), rad/s per
  /// m/s². Applied by the MCU (which knows the specific force), not by the triad itself.
  double g_sensitivity_radps_per_mps2 = 0;
};

/// From the (erroneous) physical value to the integer counts of one sample. Digital sensors use
/// oversample 1, zero offsets and no conversion noise; the Razor's analog gyros are read through
/// the 10-bit ADC with an offset and summed over `oversample` conversions.
struct TriadCountSpec {
  double count_lsb = 1;    ///< engineering units per sensor/ADC count
  double range = 1e300;    ///< the sensor saturates at ± this many engineering units
  int count_min = -32768;  ///< register / ADC limits of one conversion
  int count_max = 32767;
  double zero_count = 0;       ///< actual count at zero input (analog sensors: zero-rate level)
  int nominal_zero_count = 0;  ///< count the firmware subtracts per conversion
  int oversample = 1;          ///< conversions summed into one sample
  double conversion_noise_counts = 0;  ///< ADC transition noise per conversion (1σ)
  bool has_overflow_value = false;     ///< the sensor reports `overflow_value` when out of range
  int overflow_value = -4096;
  /// Engineering units per output LSB (what STATUS reports).
  double output_lsb() const { return count_lsb / oversample; }
};

struct TriadSpec {
  TriadErrorSpec error;
  TriadCountSpec counts;
  Sampling sampling = Sampling::kAverage;
};

/// A sinusoidal vibration picked up by the board (engine, PTO), in the IMU frame.
struct VibrationTone {
  double frequency_hz = 0;
  Eigen::Vector3d accel_amplitude_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_amplitude_radps = Eigen::Vector3d::Zero();
};

/// A named sensor set (protocol STATUS "sensor profile").
struct ImuProfile {
  std::string name;  ///< razor-v13, consumer-mems, industrial-mems, tactical
  int id = 0;        ///< STATUS profile id
  TriadSpec accel, gyro, mag;
  int default_baud = 115200;
  double mag_rate_hz = 10;  ///< compass output rate (its own oscillator)
};

/// The known profile names.
const std::vector<std::string>& ProfileNames();
/// The profile of that name. @throws std::invalid_argument for an unknown name.
ImuProfile ProfileByName(const std::string& name);

}  // namespace hil::mcu

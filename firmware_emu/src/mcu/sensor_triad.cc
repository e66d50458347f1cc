#include "hil/firmware_emu/mcu/sensor_triad.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::mcu {
namespace {

// Allan deviation of a first-order Gauss–Markov process peaks at 0.61736·σ (τ = 1.8926·τc); the
// bias-instability floor is B·√(2 ln2/π). Equating them gives σ for a configured B.
constexpr double kGaussMarkovAllanPeak = 0.6173643;
const double kFlickerFloor = std::sqrt(2.0 * std::numbers::ln2 / std::numbers::pi);
constexpr double kReferenceTemperature_c = 25.0;

}  // namespace

SensorTriad::SensorTriad(const TriadSpec& spec, double sample_period_s, std::uint64_t seed)
    : spec_(spec), period_s_(sample_period_s), rng_(seed) {
  if (!(sample_period_s > 0)) throw std::invalid_argument("SensorTriad: sample period must be > 0");
  if (spec.counts.oversample < 1)
    throw std::invalid_argument("SensorTriad: oversample must be >= 1");
  const TriadErrorSpec& e = spec_.error;
  // power-on draws: scale factor, misalignment, turn-on bias (in this order, fixed by the seed)
  for (int i = 0; i < 3; ++i) {
    scale_misalignment_(i, i) = 1.0 + e.scale_factor_sigma_ppm * 1e-6 * rng_.Normal();
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) scale_misalignment_(i, j) = e.misalignment_sigma_rad * rng_.Normal();
  for (int i = 0; i < 3; ++i) turn_on_bias_[i] = e.turn_on_bias_sigma[i] * rng_.Normal();

  if (e.bias_instability > 0 && e.flicker_terms > 0) {
    InitFlicker(seed);
  } else if (e.bias_instability > 0) {
    const double sigma = e.bias_instability * kFlickerFloor / kGaussMarkovAllanPeak;
    gm_phi_ = std::exp(-period_s_ / e.bias_correlation_time_s);
    gm_drive_ = sigma * std::sqrt(1.0 - gm_phi_ * gm_phi_);
    for (int i = 0; i < 3; ++i) gm_bias_[i] = sigma * rng_.Normal();  // stationary start
  }
  // white noise per sample, per unit of noise density
  if (spec_.sampling == Sampling::kAverage) {
    white_sigma_scale_ = 1.0 / std::sqrt(period_s_);
  } else {
    const double noise_bw_hz =
        e.bandwidth_hz > 0 ? std::numbers::pi / 2.0 * e.bandwidth_hz : 0.5 / period_s_;
    white_sigma_scale_ = std::sqrt(noise_bw_hz);
  }
}

double GaussMarkovAllanVariance(double tau_s, double tau_c_s) {
  const double x = tau_s / tau_c_s;
  return 2.0 / x * (1.0 - (3.0 - 4.0 * std::exp(-x) + std::exp(-2.0 * x)) / (2.0 * x));
}

void SensorTriad::InitFlicker(std::uint64_t seed) {
  const TriadErrorSpec& e = spec_.error;
  if (!(e.flicker_tau_min_s > 0 && e.flicker_tau_max_s >= e.flicker_tau_min_s))
    throw std::invalid_argument("SensorTriad: flicker correlation times must be 0 < min <= max");
  // a stream of its own, so that the other draws of the triad keep their order
  flicker_rng_ = Rng(seed ^ 0xF11C4E5A5EEDULL);
  const int n = e.flicker_terms;
  std::vector<double> tau_c(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const double u = n > 1 ? static_cast<double>(j) / (n - 1) : 0.5;
    tau_c[static_cast<std::size_t>(j)] =
        e.flicker_tau_min_s * std::pow(e.flicker_tau_max_s / e.flicker_tau_min_s, u);
  }
  // one σ for all terms, scaled so that the summed Allan deviation, averaged over log τ across the
  // terms' peaks (1.89 τc_min … 1.89 τc_max), equals the flicker floor B·√(2 ln2/π)
  constexpr int kGrid = 33;
  double mean = 0;
  for (int g = 0; g < kGrid; ++g) {
    const double tau =
        1.8926 * e.flicker_tau_min_s *
        std::pow(e.flicker_tau_max_s / e.flicker_tau_min_s, static_cast<double>(g) / (kGrid - 1));
    double avar = 0;
    for (double tc : tau_c) avar += GaussMarkovAllanVariance(tau, tc);
    mean += std::sqrt(avar) / kGrid;
  }
  const double sigma = e.bias_instability * kFlickerFloor / mean;
  for (double tc : tau_c) {
    const double phi = std::exp(-period_s_ / tc);
    flicker_phi_.push_back(phi);
    flicker_drive_.push_back(sigma * std::sqrt(1.0 - phi * phi));
    Eigen::Vector3d x0;
    for (int i = 0; i < 3; ++i) x0[i] = sigma * flicker_rng_.Normal();  // stationary start
    flicker_state_.push_back(x0);
  }
}

void SensorTriad::AdvanceBiases() {
  const TriadErrorSpec& e = spec_.error;
  for (std::size_t j = 0; j < flicker_state_.size(); ++j)
    for (int i = 0; i < 3; ++i)
      flicker_state_[j][i] =
          flicker_phi_[j] * flicker_state_[j][i] + flicker_drive_[j] * flicker_rng_.Normal();
  for (int i = 0; i < 3; ++i) {
    if (gm_drive_ > 0) gm_bias_[i] = gm_phi_ * gm_bias_[i] + gm_drive_ * rng_.Normal();
    if (e.bias_random_walk > 0)
      rw_bias_[i] += e.bias_random_walk * std::sqrt(period_s_) * rng_.Normal();
  }
}

Eigen::Vector3d SensorTriad::MeasureBandLimited(const Eigen::Vector3d& band_limited_I,
                                                const Eigen::Vector3d& extra_I,
                                                double temperature_c) {
  const TriadErrorSpec& e = spec_.error;
  if (!first_) AdvanceBiases();
  first_ = false;
  const double dtemp = temperature_c - kReferenceTemperature_c;
  const double scale_temp = 1.0 + e.scale_temperature_ppm_per_c * 1e-6 * dtemp;
  Eigen::Vector3d value = scale_temp * (scale_misalignment_ * (band_limited_I + extra_I));
  value += turn_on_bias_ + gm_bias_ + rw_bias_;
  for (const Eigen::Vector3d& f : flicker_state_) value += f;
  value += Eigen::Vector3d::Constant(e.bias_temperature_coeff_per_c * dtemp);
  for (int i = 0; i < 3; ++i) value[i] += e.noise_density[i] * white_sigma_scale_ * rng_.Normal();
  return value;
}

void SensorTriad::SetVibration(const std::vector<VibrationTone>& tones, bool accel) {
  tones_.clear();
  for (const VibrationTone& v : tones) {
    Tone t;
    t.omega_radps = 2.0 * std::numbers::pi * v.frequency_hz;
    t.amplitude = accel ? v.accel_amplitude_mps2 : v.gyro_amplitude_radps;
    for (int i = 0; i < 3; ++i) t.phase_rad[i] = 2.0 * std::numbers::pi * rng_.Uniform();
    tones_.push_back(t);
  }
}

Eigen::Vector3d SensorTriad::VibrationAt(double t_s) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const double bw = spec_.error.bandwidth_hz;
  for (const Tone& tone : tones_) {
    // first-order low-pass response at the tone's frequency
    double gain = 1.0, lag = 0.0;
    if (bw > 0) {
      const double r = tone.omega_radps / (2.0 * std::numbers::pi * bw);
      gain = 1.0 / std::sqrt(1.0 + r * r);
      lag = std::atan(r);
    }
    for (int i = 0; i < 3; ++i) {
      const double ph = tone.phase_rad[i] - lag;
      double v;
      if (spec_.sampling == Sampling::kAverage) {
        // exact mean of sin(ωt + φ) over [t − T, t]
        const double w = tone.omega_radps;
        v = w > 0
                ? (std::cos(w * (t_s - period_s_) + ph) - std::cos(w * t_s + ph)) / (w * period_s_)
                : std::sin(ph);
      } else {
        v = std::sin(tone.omega_radps * t_s + ph);
      }
      sum[i] += gain * tone.amplitude[i] * v;
    }
  }
  return sum;
}

Eigen::Vector3d SensorTriad::Measure(const Eigen::Vector3d& true_I, Time t, double temperature_c) {
  const TriadErrorSpec& e = spec_.error;
  // band-limit the motion (exact first-order response to a held input)
  if (first_ || e.bandwidth_hz <= 0) {
    filtered_ = true_I;
  } else {
    const double a = 1.0 - std::exp(-2.0 * std::numbers::pi * e.bandwidth_hz * period_s_);
    filtered_ += a * (true_I - filtered_);
  }
  // bias processes advance once per sample (not on the first)
  if (!first_) AdvanceBiases();
  first_ = false;
  const double scale_temp =
      1.0 + e.scale_temperature_ppm_per_c * 1e-6 * (temperature_c - kReferenceTemperature_c);
  Eigen::Vector3d value =
      scale_temp * (scale_misalignment_ * (filtered_ + VibrationAt(ToSeconds(t))));
  value += turn_on_bias_ + gm_bias_ + rw_bias_;
  for (const Eigen::Vector3d& f : flicker_state_) value += f;
  value += Eigen::Vector3d::Constant(e.bias_temperature_coeff_per_c *
                                     (temperature_c - kReferenceTemperature_c));
  for (int i = 0; i < 3; ++i) value[i] += e.noise_density[i] * white_sigma_scale_ * rng_.Normal();
  return value;
}

TriadCounts SensorTriad::Quantise(const Eigen::Vector3d& value) {
  const TriadCountSpec& c = spec_.counts;
  TriadCounts out;
  for (int i = 0; i < 3; ++i) {
    double v = value[i];
    bool sat = false;
    if (v > c.range) v = c.range, sat = true;
    if (v < -c.range) v = -c.range, sat = true;
    const double x = c.zero_count + v / c.count_lsb;
    if (c.has_overflow_value && (x > c.count_max + 0.5 || x < c.count_min - 0.5)) {
      out.counts[i] = static_cast<std::int16_t>(c.overflow_value);
      out.saturated[i] = true;
      continue;
    }
    long sum = 0;
    for (int k = 0; k < c.oversample; ++k) {
      const double noisy =
          c.conversion_noise_counts > 0 ? x + c.conversion_noise_counts * rng_.Normal() : x;
      long q = std::lround(noisy);
      if (q > c.count_max) q = c.count_max, sat = true;
      if (q < c.count_min) q = c.count_min, sat = true;
      sum += q - c.nominal_zero_count;
    }
    sum = std::clamp(sum, -32768L, 32767L);
    out.counts[i] = static_cast<std::int16_t>(sum);
    out.saturated[i] = sat;
  }
  return out;
}

}  // namespace hil::mcu

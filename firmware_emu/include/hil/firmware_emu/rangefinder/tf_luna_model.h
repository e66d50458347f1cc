#pragma once
/// @file
/// What a Benewake TF-Luna (or TFmini-S) reports for a target at a true range: signal strength,
/// range noise against strength, resolution and the invalid readings of its manual
/// (seeds_001_003.md §C.3.1).
///
/// - Strength: Amp = K · ρ · cos θ / r², K from `amp_white_8m` (the Amp of a 90 % white target
///   facing the module at 8 m: the manual's 8 m range on white ends where Amp falls to the
///   threshold), capped at 65534; 65535 (overexposure) only when the formula reaches it.
///   Without a target within the cast range Amp = `ambient_amp`.
/// - Noise at 100 Hz (manual): σ = 3 cm at Amp ≤ 200, 2 cm at 400, 1 cm at 1000, 0.5 cm at
///   ≥ 2000, interpolated in log Amp; the output averages 500/rate internal samples, so σ scales
///   with √(rate/100).
/// - Invalid: Amp < amp_threshold (default 100), Amp = 65535, inside the 0.2 m blind zone or
///   beyond the distance limit (default 900 cm): TF-Luna reports Dist = dummy_dist (default 0),
///   TFmini-S −1 (0xFFFF) for a weak signal and −2 (0xFFFE, Amp 0xFFFF) for saturation.
/// The model constants K, ambient Amp and the blind-zone reading are this project's choice
/// (UNVERIFIED); the table values are the manual's.

#include <cstdint>

#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/rangefinder/benewake_codec.h"

namespace hil::rangefinder {

enum class ModuleModel { kTfLuna, kTfminiS };

struct RangeModelConfig {
  ModuleModel model = ModuleModel::kTfLuna;
  double amp_white_8m = 120;  ///< Amp of a 90 % white target at 8 m, facing the module
  double ambient_amp = 12;    ///< Amp with nothing in range (UNVERIFIED)
  std::uint16_t amp_threshold = 100;
  std::uint16_t dummy_dist = 0;  ///< TF-Luna's dummy_dist
  double blind_zone_m = 0.2;
  double distance_limit_m = 9.0;  ///< TF-Luna default limit [0, 900] cm
};

/// The target as the beam sees it (none: nothing within the cast range).
struct Target {
  bool present = false;
  double range_m = 0;
  double reflectivity = 0.3;
  double cos_incidence = 1;
};

/// One reading before framing, with the continuous value behind it (for golden expectations).
struct Reading {
  DataFields fields;
  bool valid = false;
  double measured_m = 0;  ///< true range + noise, before quantisation (0 when invalid)
  double sigma_m = 0;     ///< the noise standard deviation used
};

/// σ of the range at 100 Hz for a strength (manual table).
double RangeSigma100Hz_m(double amp);
/// Amp for a target (uncapped).
double StrengthOf(const RangeModelConfig& c, const Target& t);
/// One reading at `frame_rate_hz` in `format` (cm or mm: PIX uses cm values), drawing the noise
/// from `rng`.
Reading Measure(const RangeModelConfig& c, const Target& t, double frame_rate_hz,
                OutputFormat format, double chip_temperature_c, mcu::Rng& rng);

}  // namespace hil::rangefinder

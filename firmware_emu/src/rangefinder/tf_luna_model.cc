#include "hil/firmware_emu/rangefinder/tf_luna_model.h"

#include <algorithm>
#include <cmath>

namespace hil::rangefinder {
namespace {

constexpr double kWhite = 0.9, kRangeWhite_m = 8.0;
constexpr std::uint16_t kSaturated = 0xFFFF;

}  // namespace

double RangeSigma100Hz_m(double amp) {
  // (Amp, σ) of the TF-Luna manual, interpolated in log Amp, flat beyond the ends
  static constexpr double kAmp[] = {200, 400, 1000, 2000};
  static constexpr double kSigma_m[] = {0.03, 0.02, 0.01, 0.005};
  if (amp <= kAmp[0]) return kSigma_m[0];
  for (int k = 1; k < 4; ++k) {
    if (amp <= kAmp[k]) {
      const double w = std::log(amp / kAmp[k - 1]) / std::log(kAmp[k] / kAmp[k - 1]);
      return kSigma_m[k - 1] + w * (kSigma_m[k] - kSigma_m[k - 1]);
    }
  }
  return kSigma_m[3];
}

double StrengthOf(const RangeModelConfig& c, const Target& t) {
  if (!t.present) return c.ambient_amp;
  const double k = c.amp_white_8m * kRangeWhite_m * kRangeWhite_m / kWhite;
  const double r = std::max(t.range_m, 0.01);
  return c.ambient_amp + k * t.reflectivity * std::max(t.cos_incidence, 0.0) / (r * r);
}

Reading Measure(const RangeModelConfig& c, const Target& t, double frame_rate_hz,
                OutputFormat format, double chip_temperature_c, mcu::Rng& rng) {
  Reading out;
  const double amp = StrengthOf(c, t);
  out.fields.amp = amp >= 65535.0 ? kSaturated : static_cast<std::uint16_t>(std::lround(amp));
  out.fields.temp_raw = TemperatureToRaw(chip_temperature_c);
  out.sigma_m = RangeSigma100Hz_m(amp) * std::sqrt(std::max(frame_rate_hz, 1.0) / 100.0);
  const double noise =
      rng.Normal();  // drawn for every frame: the stream does not depend on validity
  const bool saturated = out.fields.amp == kSaturated;
  const bool weak = out.fields.amp < c.amp_threshold;
  const double measured = t.range_m + out.sigma_m * noise;
  const bool in_range = t.present && t.range_m >= c.blind_zone_m && measured <= c.distance_limit_m;
  out.valid = !saturated && !weak && in_range;
  const bool tfmini = c.model == ModuleModel::kTfminiS;
  if (!out.valid) {
    out.fields.dist = !tfmini ? c.dummy_dist : saturated ? 0xFFFE : 0xFFFF;
    return out;
  }
  out.measured_m = std::max(measured, 0.0);
  const double unit = format == OutputFormat::kMm9Byte ? 1000.0 : 100.0;
  out.fields.dist =
      static_cast<std::uint16_t>(std::min(std::lround(out.measured_m * unit), 65000L));
  return out;
}

}  // namespace hil::rangefinder

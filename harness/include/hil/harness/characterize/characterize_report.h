#pragma once
/// @file
/// What hil characterize writes: the JSON document (--json), the SVG plots for people (--svg DIR:
/// allan_gyro.svg, allan_accel.svg, psd_gyro.svg, psd_accel.svg; log10 axes, with data-sheet
/// reference lines when given) and the summary it prints. Units in the JSON keys; the noise terms
/// per axis as {x, y, z} objects beside the curves.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "hil/harness/characterize/characterize.h"

namespace hil::harness {

/// Data-sheet figures drawn against the measured curves (and copied into the JSON).
struct CharacterizeReferences {
  std::optional<double> arw_deg_per_rthr, vrw_mps_per_rthr;
  std::optional<double> gyro_bias_instability_degph, accel_bias_instability_mps2;
  std::string label = "reference";
};

nlohmann::json CharacterizationJson(const Characterization& c, const std::string& source,
                                    const CharacterizeReferences& ref);

/// @throws std::runtime_error when the folder or a file cannot be written.
void WriteCharacterizationSvgs(const Characterization& c, const CharacterizeReferences& ref,
                               const std::string& dir);

/// The analysed samples as CSV (`t_s,gx_radps,gy_radps,gz_radps,ax_mps2,ay_mps2,az_mps2`, the
/// cell start times on the log's time scale), for checking the curves with another tool.
/// @throws std::runtime_error when the file cannot be written.
void WriteAnalysedSamplesCsv(const Characterization& c, const std::string& path);

/// A few lines for people: window, ARW, VRW, bias instability per axis.
std::string CharacterizationSummary(const Characterization& c);

}  // namespace hil::harness

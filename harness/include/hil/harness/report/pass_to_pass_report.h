#pragma once
/// @file
/// Closed loop: the ISO 12188-2 style pass-to-pass figures (eval/pass_to_pass.h) in report.json
/// (`pass_to_pass`), in the HTML report (a table) and as criteria (`pass_to_pass.<method>.<field>`:
/// method nearest_point, interpolated or absolute; field mean_m, mean_abs_m, p95_abs_m, max_abs_m;
/// and pass_to_pass.method_difference_max_m, pass_to_pass.pairs). A figure without samples is
/// absent (null), so a bound on it fails.

#include <map>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "hil/harness/eval/pass_to_pass.h"

namespace hil::harness {

nlohmann::json PassToPassJson(const PassToPassMetrics& m);
void AddPassToPassMetrics(const std::optional<PassToPassMetrics>& m,
                          std::map<std::string, std::optional<double>>& table);
/// The HTML section: a table of both methods and the absolute figures, then one row per pair.
void AppendPassToPassHtml(std::string& html, const PassToPassMetrics& m);

}  // namespace hil::harness

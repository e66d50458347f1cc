#pragma once
/// @file
/// The suite's side-by-side report: for each scenario file, the mean and spread over its seeds of
/// every criterion's value (pass/fail per criterion: it passed in every seed), of every reference
/// figure's metric from the scenario's `paper:` section (beside the paper's figure and the raw
/// GNSS baseline), and of each GNSS outage's maximum east, north, up and horizontal error.
/// Written as OUT/summary.json (`scenarios`) and OUT/report.md.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// What the suite knows of one scenario file before running it.
struct SuiteScenarioInfo {
  std::string file;
  std::optional<Scenario> scenario;  ///< absent when the file is invalid
  std::string error;                 ///< the validation message when it is
};

/// Mean, sample standard deviation, min and max of the numbers among `values` (nulls skipped):
/// {"n", "mean", "std", "min", "max"}; n = 0 and nulls when there are none.
nlohmann::json SpreadOf(const std::vector<nlohmann::json>& values);

/// One entry per scenario file, from the runs' summary entries (each with `scenario_file`,
/// `pass`, `seed`, `exit_code` and, when the run produced a report, `metric_table`,
/// `baseline_table`, `criteria`, `outages`).
nlohmann::json SummariseScenarios(const std::vector<SuiteScenarioInfo>& scenarios,
                                  const nlohmann::json& runs);

/// The Markdown report of a summary (`title`, `scenario_dir`, `scenarios`, `passed`, `failed`,
/// `invalid`, `short_form`, `seeds`, `runs`). No wall times: the same bytes whoever ran the runs.
std::string SuiteMarkdown(const nlohmann::json& summary);

}  // namespace hil::harness

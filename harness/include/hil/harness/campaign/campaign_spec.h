#pragma once
/// @file
/// A campaign file (YAML, format in vectors/campaigns/README.md): which scenarios (globs, beside
/// the file), which seeds (a range or a list), which sweeps (a scenario field path → a list of
/// values, as a cartesian product or zipped) and which criteria across runs (a statistic over the
/// seeds of a metric against a bound; a pass fraction). Read strictly: every error is a
/// ScenarioError naming the campaign file, the line and the field (exit code 2).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hil/harness/scenario/campaign_criterion.h"
#include "hil/harness/scenario/scenario_overrides.h"

namespace hil::harness {

class YamlReader;

/// One swept scenario field and the values it takes (each as YAML text).
struct SweepField {
  std::string field;
  std::vector<std::string> values;
};

/// A campaign as its file (or `hil suite`'s options) gives it.
struct CampaignSpec {
  std::string file;  ///< the campaign file ("" for `hil suite`)
  std::string name, description;
  std::string title;   ///< the report's heading
  std::string source;  ///< what the scenarios came from: the campaign file, or the suite's folder
  std::vector<std::string> scenario_files;  ///< in run order, each once
  bool short_form = false;
  std::vector<std::uint64_t> seeds;  ///< empty: each scenario's own seed, one run
  /// A scenario file's own seeds, instead of `seeds` (`hil suite`: a scenario's `statistical:`
  /// section asks for its seeds).
  std::map<std::string, std::vector<std::uint64_t>> file_seeds;
  bool zip = false;  ///< sweep values zipped (i-th with i-th) instead of crossed
  std::vector<SweepField> sweep;
  std::vector<CampaignCriterion> criteria;
  std::vector<std::string> run_args;  ///< passed to every `hil run` (--mode, --speed, --estimator)
};

/// Reads and validates a campaign file, including every sweep value against every scenario (a
/// value the scenario rejects is reported at the value's line). @throws ScenarioError.
CampaignSpec ReadCampaignFile(const std::string& path);

/// The sweep's points in order: each the overrides of one point (one empty point without sweeps).
std::vector<std::vector<ScenarioOverride>> SweepPoints(const CampaignSpec& spec);

}  // namespace hil::harness

#pragma once
/// @file
/// Loading a scenario: the loader of the scenario stage (scenario/scenario_reader.h) with the
/// devices' sections read by the device table (device_kind.h).

#include <string>
#include <vector>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/scenario_keys.h"
#include "hil/harness/scenario/scenario_overrides.h"

namespace hil::harness {

/// Loads and validates a scenario file; `include:` files are looked up beside it, then in
/// ScenarioLibraryDirs(). With `short_form`, the keys of the file's `short:` section (if any)
/// replace the top-level keys of the same name first (`hil run --short`, `hil suite --short`);
/// then, after the includes, each of `overrides` sets one field (`hil run --set`, a campaign's
/// sweeps; scenario_overrides.h). @throws ScenarioError.
Scenario LoadScenario(const std::string& path, bool short_form = false,
                      const std::vector<ScenarioOverride>& overrides = {});
/// Loads the embedded default scenario (vectors/scenarios/default.yaml, compiled in).
Scenario LoadDefaultScenario();
/// Parses scenario text; `name` stands for the file in messages. @throws ScenarioError.
Scenario ParseScenario(const std::string& text, const std::string& name);
/// The scenario reference (`hil scenario-keys`, docs/scenario_reference.md): every table of
/// scenario_keys.h, and the names of the top-level sections (the loader's and the device
/// table's) that have no table yet.
std::string ScenarioReference();
/// Every table of scenario_keys.h: the scenario stage's, then the devices' (device_key_tables.cc).
std::vector<const KeySection*> ScenarioKeyTables();

}  // namespace hil::harness

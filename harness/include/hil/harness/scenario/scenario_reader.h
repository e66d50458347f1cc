#pragma once
/// @file
/// The scenario loader below the device table: it reads every section of a scenario file but the
/// devices', which the device table (devices/device_kind.h) reads through DeviceSections. Load
/// scenarios with LoadScenario (devices/scenario_file.h), which passes the table.

#include <functional>
#include <string>
#include <vector>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/scenario_overrides.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

/// The devices' part of the scenario file.
struct DeviceSections {
  std::vector<std::string> keys;  ///< the top-level keys the devices' readers read
  /// Reads them into the scenario, after start_utc, the truth, `can:` and `greenhouse:`, before
  /// the closed loop and the estimator.
  std::function<void(const YamlReader& root, Scenario& s)> read;
};

/// The top-level keys the loader reads itself (every one but the devices').
std::vector<std::string> ScenarioOwnKeys();

/// LoadScenario (devices/scenario_file.h) with the devices' sections read by `devices`.
/// @throws ScenarioError.
Scenario LoadScenarioFile(const std::string& path, bool short_form,
                          const std::vector<ScenarioOverride>& overrides,
                          const DeviceSections& devices);
/// ParseScenario (devices/scenario_file.h) with the devices' sections read by `devices`.
/// @throws ScenarioError.
Scenario ParseScenarioText(const std::string& text, const std::string& name,
                           const DeviceSections& devices);
/// The embedded default scenario (vectors/scenarios/default.yaml, compiled in).
const char* DefaultScenarioText();

}  // namespace hil::harness

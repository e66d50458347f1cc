#pragma once
/// @file
/// Scenario field overrides: `hil run --set gnss.baud=38400` and a campaign's sweeps set one field
/// of a scenario (a dotted path with `[i]` list indices, e.g. `faults[0].duration_s`) to a YAML
/// value after its includes are resolved, so the value is checked like the file's own.

#include <string>
#include <vector>

namespace hil::harness {

class YamlReader;

/// One field set from outside the scenario file.
struct ScenarioOverride {
  std::string field;  ///< dotted path: `gnss.model.horizontal_sigma_m`, `faults[1].start_s`
  std::string value;  ///< YAML text of the value (`38400`, `[1, 2]`, `{a: 1}`)
  /// What errors in it name instead of a file and line; empty: `--set FIELD=VALUE`.
  std::string origin;
};

/// "FIELD=VALUE" as an override. @throws std::invalid_argument naming what is wrong.
ScenarioOverride ParseOverride(const std::string& text);

/// The path's segments: keys, and list indices as "[i]" (`a.b[2]` → "a", "b", "[2]").
/// @throws std::invalid_argument for an empty key or a malformed index.
std::vector<std::string> SplitFieldPath(const std::string& field);

/// Sets each override's field in the root mapping (in order). The parent of the last segment
/// must exist (a mapping, or a list holding the index); the last key may be new.
/// @throws ScenarioError naming the override (its origin) and the field; a value the scenario
/// then rejects names the override too (YamlReader::NoteOrigin), not the scenario file's line.
void ApplyOverrides(YamlReader& root, const std::vector<ScenarioOverride>& overrides);

}  // namespace hil::harness

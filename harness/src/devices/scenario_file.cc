#include "hil/harness/devices/scenario_file.h"

#include <algorithm>

#include "hil/harness/devices/device_kind.h"
#include "hil/harness/scenario/scenario_keys.h"
#include "hil/harness/scenario/scenario_reader.h"

namespace hil::harness {
namespace {

// The device table's sections: every row's keys, and its readers in table order.
DeviceSections TableSections() {
  DeviceSections d;
  for (const DeviceKind* k : DeviceKinds()) {
    for (std::string_view key : k->sections) d.keys.emplace_back(key);
  }
  d.read = [](const YamlReader& root, Scenario& s) {
    for (const DeviceKind* k : DeviceKinds()) {
      if (k->read) k->read(root, s);
    }
  };
  return d;
}

}  // namespace

Scenario LoadScenario(const std::string& path, bool short_form,
                      const std::vector<ScenarioOverride>& overrides) {
  return LoadScenarioFile(path, short_form, overrides, TableSections());
}

Scenario ParseScenario(const std::string& text, const std::string& name) {
  return ParseScenarioText(text, name, TableSections());
}

std::vector<const KeySection*> ScenarioKeyTables() {
  std::vector<const KeySection*> all(ScenarioKeySections().begin(), ScenarioKeySections().end());
  all.insert(all.end(), DeviceKeySections().begin(), DeviceKeySections().end());
  return all;
}

std::string ScenarioReference() {
  const std::vector<const KeySection*> tables = ScenarioKeyTables();
  std::vector<std::string> tabled;  // the top level's own keys, and the sections with a table
  for (const KeySection* s : tables) {
    if (s->path.empty()) {
      for (const ScenarioKey& k : s->keys) tabled.emplace_back(k.name);
    } else {
      const std::string_view p = s->path;
      tabled.emplace_back(p.substr(0, std::min(p.find('.'), p.find('['))));
    }
  }
  std::vector<std::string> others = ScenarioOwnKeys();
  const std::vector<std::string> devices = TableSections().keys;
  others.insert(others.end(), devices.begin(), devices.end());
  std::erase_if(others, [&tabled](const std::string& k) {
    return std::find(tabled.begin(), tabled.end(), k) != tabled.end();
  });
  return ScenarioReferenceMarkdown(tables, others);
}

Scenario LoadDefaultScenario() {
  return ParseScenario(DefaultScenarioText(), "<embedded default scenario>");
}

}  // namespace hil::harness

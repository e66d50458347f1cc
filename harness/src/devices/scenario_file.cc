#include "hil/harness/devices/scenario_file.h"

#include "hil/harness/devices/device_kind.h"
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

Scenario LoadDefaultScenario() {
  return ParseScenario(DefaultScenarioText(), "<embedded default scenario>");
}

}  // namespace hil::harness

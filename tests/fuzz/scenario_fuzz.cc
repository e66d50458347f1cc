// Fuzz target: the scenario loader accepts a document or rejects it with a ScenarioError that names
// a line; no other exception, crash or sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hil::harness::ParseScenario(text, "fuzz.yaml");
  } catch (const hil::harness::ScenarioError& e) {
    if (e.line() < 0) std::abort();
  } catch (const YAML::Exception&) {
    // yaml-cpp's own errors beyond parsing (e.g. deep nesting) must be turned into ScenarioErrors
    std::abort();
  }
  return 0;
}

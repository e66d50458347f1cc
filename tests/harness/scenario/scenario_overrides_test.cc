// Scenario overrides (`hil run --set`, campaign sweeps): a field path into mappings and lists,
// set after the includes, checked like the file's own value; errors name the file and the field.
#include "hil/harness/scenario/scenario_overrides.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

std::string ScenarioFile(const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("hil_overrides_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "s.yaml").string();
  std::ofstream(path) << text;
  return path;
}

constexpr const char* kBase =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n"
    "duration_s: 300\n"
    "gnss: {baud: 9600}\n"
    "criteria:\n"
    "  - {metric: horizontal_rmse_m, max: 1.0}\n";

TEST(ScenarioOverridesTest, SplitsPathsAndParsesAssignments) {
  EXPECT_EQ(SplitFieldPath("a.b[2].c"), (std::vector<std::string>{"a", "b", "[2]", "c"}));
  EXPECT_EQ(SplitFieldPath("faults[0]"), (std::vector<std::string>{"faults", "[0]"}));
  const ScenarioOverride o = ParseOverride("gnss.baud=38400");
  EXPECT_EQ(o.field, "gnss.baud");
  EXPECT_EQ(o.value, "38400");
  EXPECT_THROW(ParseOverride("gnss.baud"), std::invalid_argument);
  EXPECT_THROW(ParseOverride("=1"), std::invalid_argument);
  EXPECT_THROW(SplitFieldPath("a..b"), std::invalid_argument);
  EXPECT_THROW(SplitFieldPath("a[x]"), std::invalid_argument);
  EXPECT_THROW(SplitFieldPath("[0].a"), std::invalid_argument);
}

TEST(ScenarioOverridesTest, SetsMappingKeysAndListElements) {
  const std::string path = ScenarioFile(kBase);
  const Scenario s = LoadScenario(
      path, false, {{"gnss.baud", "38400"}, {"criteria[0].max", "0.5"}, {"duration_s", "120"}});
  EXPECT_EQ(s.gnss.baud, 38400);
  EXPECT_DOUBLE_EQ(s.duration_s, 120.0);
  ASSERT_EQ(s.criteria.size(), 1u);
  EXPECT_DOUBLE_EQ(*s.criteria[0].max, 0.5);
  EXPECT_EQ(LoadScenario(path).gnss.baud, 9600);  // the file itself is untouched
}

TEST(ScenarioOverridesTest, BadOverridesNameTheField) {
  const std::string path = ScenarioFile(kBase);
  const auto expect = [&](const ScenarioOverride& o, const std::string& fragment) {
    try {
      LoadScenario(path, false, {o});
      FAIL() << o.field;
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect({"gnss.nosuch.x", "1"}, "no 'gnss.nosuch'");
  expect({"criteria[3].max", "1"}, "no 'criteria[3]'");
  expect({"criteria[3]", "1"}, "no element [3]");
  expect({"duration_s", "-4"}, "duration_s");  // checked like the file's own value
  expect({"gnss.bad_key", "1"}, "gnss.bad_key");
}

}  // namespace
}  // namespace hil::harness

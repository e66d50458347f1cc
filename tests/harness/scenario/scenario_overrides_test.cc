// Scenario overrides (`hil run --set`, campaign sweeps): a field path into mappings and lists,
// set after the includes, checked like the file's own value; errors name the file and the field.
#include "hil/harness/scenario/scenario_overrides.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "process_temp_dir.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

std::string ScenarioFile(const std::string& text) {
  const fs::path dir = test::ProcessTempDir("overrides");
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
      path, false,
      {{"gnss.baud", "38400", ""}, {"criteria[0].max", "0.5", ""}, {"duration_s", "120", ""}});
  EXPECT_EQ(s.gnss.baud, 38400);
  EXPECT_DOUBLE_EQ(s.duration_s, 120.0);
  ASSERT_EQ(s.criteria.size(), 1u);
  EXPECT_DOUBLE_EQ(*s.criteria[0].max, 0.5);
  EXPECT_EQ(LoadScenario(path).gnss.baud, 9600);  // the file itself is untouched
}

TEST(ScenarioOverridesTest, BadOverridesNameTheOverrideNotTheFile) {
  const std::string path = ScenarioFile(kBase);
  const auto expect = [&](const ScenarioOverride& o, const std::string& fragment) {
    try {
      LoadScenario(path, false, {o});
      FAIL() << o.field;
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.file(), "--set " + o.field + "=" + o.value) << e.what();
      EXPECT_EQ(e.line(), 0) << e.what();  // no line of the scenario file
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect({"gnss.nosuch.x", "1", ""}, "no 'gnss.nosuch'");
  expect({"criteria[3].max", "1", ""}, "no 'criteria[3]'");
  expect({"criteria[3]", "1", ""}, "no element [3]");
  expect({"duration_s", "-4", ""}, "duration_s");  // checked like the file's own value
  expect({"gnss.bad_key", "1", ""}, "gnss.bad_key");
  expect({"seed", "abc", ""}, "seed: expected an integer, got 'abc'");
  expect({"gnss.baud", "fast", ""}, "gnss.baud: expected an integer");
  expect({"gnss", "{baud: fast}", ""}, "gnss.baud: expected an integer");
  expect({"criteria[0]", "{metric: nope, max: 1}", ""}, "unknown metric");
  try {  // the line is the value's own (YAML text of several lines may be given)
    LoadScenario(path, false, {{"gnss", "{baud: 1, baud: 2}", ""}});
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "--set gnss={baud: 1, baud: 2}");
    EXPECT_NE(std::string(e.what()).find("gnss.baud: duplicate key"), std::string::npos);
  }
}

TEST(ScenarioOverridesTest, AnOverridesOwnOriginIsNamed) {
  const std::string path = ScenarioFile(kBase);
  try {
    LoadScenario(path, false, {{"seed", "x", "campaign sweep seed=x"}});
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "campaign sweep seed=x");
  }
  // a value the file itself gives wrong still names the file and its line
  const std::string bad = ScenarioFile(std::string(kBase) + "seed: abc\n");
  try {
    LoadScenario(bad, false, {{"gnss.baud", "38400", ""}});
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), bad);
    EXPECT_EQ(e.line(), 7);
  }
}

}  // namespace
}  // namespace hil::harness

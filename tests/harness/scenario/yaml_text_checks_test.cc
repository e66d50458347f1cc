// What yaml-cpp lets through and a scenario must refuse: a key given twice (at any depth, in an
// included file too), a tab in the indentation, an empty key and a line of another file read as
// a key; each error names the file, the line and the field.
#include "hil/harness/scenario/yaml_text_checks.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

namespace fs = std::filesystem;

constexpr const char* kMinimal =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n";

ScenarioError ErrorOf(const std::string& text) {
  try {
    ParseScenario(text, "s.yaml");
  } catch (const ScenarioError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a ScenarioError for:\n" << text;
  return ScenarioError("", 0, "", "none");
}

TEST(YamlTextChecksTest, ADuplicateTopLevelKeyIsAnError) {
  const ScenarioError e = ErrorOf(Joined(kMinimal, "seed: 1\nseed: 7\n"));
  EXPECT_EQ(e.line(), 4) << e.what();
  EXPECT_EQ(e.field(), "seed");
  EXPECT_NE(std::string(e.what()).find("duplicate key: already given on line 3"), std::string::npos)
      << e.what();
}

TEST(YamlTextChecksTest, ADuplicateNestedKeyIsAnError) {
  const ScenarioError e = ErrorOf(Joined(kMinimal, "gnss:\n  baud: 9600\n  baud: 38400\n"));
  EXPECT_EQ(e.line(), 5) << e.what();
  EXPECT_EQ(e.field(), "gnss.baud");
  const ScenarioError f =
      ErrorOf(Joined(kMinimal, "criteria:\n  - {metric: cep95_m, max: 1, max: 2}\n"));
  EXPECT_EQ(f.line(), 4) << f.what();
  EXPECT_EQ(f.field(), "criteria[0].max");
}

TEST(YamlTextChecksTest, ADuplicateKeyInAnIncludedFileNamesThatFile) {
  const fs::path dir = fs::temp_directory_path() / ("hil_dup_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "rig.yaml") << "gnss:\n  rate_hz: 1\n  rate_hz: 5\n";
  std::ofstream(dir / "s.yaml") << kMinimal << "include: rig.yaml\n";
  try {
    LoadScenario((dir / "s.yaml").string());
    FAIL() << "a duplicate key in an include was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), (dir / "rig.yaml").string());
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_EQ(e.field(), "gnss.rate_hz");
  }
  fs::remove_all(dir);
}

TEST(YamlTextChecksTest, ATabInTheIndentationIsNamed) {
  const ScenarioError e = ErrorOf(Joined(kMinimal, "gnss:\n\tbaud: 9600\n"));
  EXPECT_EQ(e.line(), 4) << e.what();
  EXPECT_NE(std::string(e.what()).find("a tab in the indentation"), std::string::npos) << e.what();
  // a tab inside a block scalar's text is content, not indentation
  EXPECT_NO_THROW(ParseScenario(Joined(kMinimal, "description: |\n  a\tb\n  \tc\n"), "s"));
}

TEST(YamlTextChecksTest, AnEmptyKeyIsNamed) {
  for (const char* line : {": 5\n", "\"\": 5\n"}) {
    const ScenarioError e = ErrorOf(Joined(kMinimal, line));
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("an empty key"), std::string::npos) << e.what();
  }
}

TEST(YamlTextChecksTest, AKeyThatIsNotANameIsNotEchoed) {
  const ScenarioError e = ErrorOf(Joined(kMinimal, "root:$y$secret:19000:0:7:::\n"));
  EXPECT_EQ(std::string(e.what()).find("secret"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("not a scenario key name"), std::string::npos) << e.what();
  EXPECT_TRUE(IsPlainKey("rate_hz"));
  EXPECT_FALSE(IsPlainKey(""));
  EXPECT_FALSE(IsPlainKey("a b"));
}

TEST(YamlTextChecksTest, ANonFiniteWaypointNamesTheField) {
  for (const char* bad : {".nan", ".inf", "-.inf"}) {
    const ScenarioError e =
        ErrorOf(Joined(kMinimal, "path:\n  type: waypoints\n  points: [[0, 0], [", bad, ", 5]]\n"));
    EXPECT_EQ(e.field(), "path.points[1]") << e.what();
    EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
    const ScenarioError f = ErrorOf(Joined(
        kMinimal, "path:\n  type: waypoints\n  points: [[0, 0], {enu_m: [5, ", bad, "]}]\n"));
    EXPECT_EQ(f.field(), "path.points[1].enu_m") << f.what();
    EXPECT_NE(std::string(f.what()).find("finite"), std::string::npos) << f.what();
  }
}

}  // namespace
}  // namespace hil::harness

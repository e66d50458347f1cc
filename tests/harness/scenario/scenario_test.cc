#include "hil/harness/scenario/scenario.h"

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kMinimal =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n";

void ExpectError(const std::string& text, int line, const std::string& field,
                 const std::string& fragment) {
  try {
    ParseScenario(text, "s.yaml");
    FAIL() << "expected a ScenarioError for:\n" << text;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ScenarioTest, DefaultScenarioLoads) {
  const Scenario s = LoadDefaultScenario();
  EXPECT_EQ(s.name, "default_straight_line");
  EXPECT_NEAR(s.truth.speed_mps, 1.6 / 3.6, 1e-12);
  EXPECT_DOUBLE_EQ(s.truth.origin.lat_deg, 35.4796096);
  EXPECT_FALSE(s.criteria.empty());
}

TEST(ScenarioTest, UnknownKeyNamesLineAndField) {
  ExpectError(Joined(kMinimal, "duration_s: 10\nbogus: 1\n"), 4, "bogus", "unknown key");
}

TEST(ScenarioTest, MisspeltKeySuggestsTheRightOne) {
  ExpectError(Joined(kMinimal, "gnss:\n  baud: 9600\n  rate_hx: 1\n"), 5, "gnss.rate_hx",
              "did you mean 'rate_hz'");
}

TEST(ScenarioTest, WrongTypeNamesLineAndField) {
  ExpectError(Joined(kMinimal, "gnss:\n  baud: fast\n"), 4, "gnss.baud", "expected an integer");
  ExpectError(Joined(kMinimal, "duration_s: [1, 2]\n"), 3, "duration_s", "expected a number");
}

TEST(ScenarioTest, OutOfRangeAndMissingValues) {
  ExpectError(Joined(kMinimal, "duration_s: -5\n"), 3, "duration_s", "out of range");
  ExpectError("name: t\n", 1, "", "missing required key 'origin'");
  ExpectError(Joined(kMinimal, "criteria:\n  - {metric: horizontal_rmse_m}\n"), 4, "criteria[0]",
              "needs 'max'");
  ExpectError(Joined(kMinimal, "start_utc: yesterday\n"), 3, "start_utc", "ISO 8601");
}

TEST(ScenarioTest, CriterionMetricsByNameOrFamily) {
  const Scenario s =
      ParseScenario(Joined(kMinimal,
                           "criteria:\n"
                           "  - {metric: rtk_rover.heading_rms_error_deg, max: 1}\n"
                           "  - {metric: rtk_rover.time_to_first_fixed_s, max: 60}\n"
                           "  - {metric: pass_to_pass.interpolated.p95_abs_m, max: 1}\n"),
                    "s.yaml");
  ASSERT_EQ(s.criteria.size(), 3U);
  EXPECT_EQ(s.criteria[0].metric, "rtk_rover.heading_rms_error_deg");
  EXPECT_TRUE(IsCriterionMetric("horizontal_rmse_m"));
  EXPECT_TRUE(IsCriterionMetric("navd.flag.imu_lost"));
  EXPECT_FALSE(IsCriterionMetric("rtk_rovers.epochs"));
  EXPECT_FALSE(IsCriterionMetric("heading"));
  // the message lists the families too
  ExpectError(Joined(kMinimal, "criteria:\n  - {metric: rtk.heading, max: 1}\n"), 4,
              "criteria[0].metric", "rtk_rover.*");
}

TEST(ScenarioTest, SyntaxErrorAndMissingFile) {
  ExpectError("name: t\norigin: {lat_deg: 1\n", 3, "", "YAML syntax error");
  try {
    LoadScenario("/nonexistent/scenario.yaml");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scenario.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace hil::harness

// Every scenario of vectors/scenarios loads in its full and its short form, and the acceptance
// scenarios carry the papers' reference figures the suite report shows.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"
#include "hil/harness/suite/suite.h"

namespace hil::harness {
namespace {

std::string Dir() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/vectors/scenarios";
}

TEST(ScenarioFilesTest, EveryScenarioLoadsFullAndShort) {
  const auto files = SuiteScenarios(Dir());
  ASSERT_GE(files.size(), 9u);
  for (const auto& f : files) {
    for (const bool short_form : {false, true}) {
      try {
        const Scenario s = LoadScenario(f, short_form);
        EXPECT_EQ(s.short_form, short_form && s.has_short_form) << f;
        if (s.short_form) {
          EXPECT_LT(s.duration_s, LoadScenario(f).duration_s)
              << f << ": a short form should be shorter";
        }
      } catch (const ScenarioError& e) {
        ADD_FAILURE() << (short_form ? "short form: " : "") << e.what();
      }
    }
  }
}

TEST(ScenarioFilesTest, PapersFiguresComeFromTheScenarioFiles) {
  // paper 000's four methods and paper 004's outage bound
  const std::map<std::string, std::pair<std::string, double>> expected{
      {"seed000_gps_only", {"horizontal_rmse_m", 0.391}},
      {"seed000_three_gps", {"horizontal_rmse_m", 0.313}},
      {"seed000_gps_imu", {"horizontal_rmse_m", 0.234}},
      {"seed004_outages", {"outage_max_enu_error_m", 0.11}},
  };
  for (const auto& [name, figure] : expected) {
    const Scenario s = LoadScenario(Dir() + "/" + name + ".yaml");
    ASSERT_FALSE(s.paper.empty()) << name;
    EXPECT_EQ(s.paper[0].metric, figure.first) << name;
    ASSERT_TRUE(s.paper[0].value) << name;
    EXPECT_DOUBLE_EQ(*s.paper[0].value, figure.second) << name;
    EXPECT_FALSE(s.criteria.empty()) << name;
  }
  const Scenario imu = LoadScenario(Dir() + "/seed000_imu_only.yaml");
  ASSERT_FALSE(imu.paper.empty());
  EXPECT_NE(imu.paper[0].finding.find("diverges"), std::string::npos);
  // three receivers: navd reads all three, 5.2 m apart
  const Scenario three = LoadScenario(Dir() + "/seed000_three_gps.yaml");
  EXPECT_EQ(three.estimator.navd_mode, NavdMode::kMultiGnss);
  ASSERT_EQ(three.gnss.receivers.size(), 3u);
  EXPECT_NEAR((three.gnss.receivers[0].p_BA_B_m - three.gnss.receivers[1].p_BA_B_m).norm(), 5.196,
              1e-3);
  // every variant justifies its thresholds with criteria
  for (const auto& f : SuiteScenarios(Dir())) {
    if (std::filesystem::path(f).filename().string().rfind("variant_", 0) == 0) {
      EXPECT_FALSE(LoadScenario(f).criteria.empty()) << f;
    }
  }
}

// Paper 003 in the closed loop: each initial state and the rectangle with both controllers, the
// paper's figures as tracking metrics, the fuzzy rectangle held to the paper's 14.4 cm.
TEST(ScenarioFilesTest, Paper003ClosedLoopScenariosCarryThePapersFigures) {
  const std::map<std::string, double> mean_m{
      {"line1_fuzzy", 0.287},        {"line2_fuzzy", 0.238},
      {"line3_fuzzy", 0.169},        {"line4_fuzzy", 0.201},
      {"line1_pure_pursuit", 0.372}, {"line2_pure_pursuit", 0.353},
      {"line3_pure_pursuit", 0.244}, {"line4_pure_pursuit", 0.283},
      {"rectangle_fuzzy", 0.144},    {"rectangle_pure_pursuit", 0.369}};
  for (const auto& [name, value] : mean_m) {
    const Scenario s = LoadScenario(Dir() + "/seed003_" + name + ".yaml");
    EXPECT_TRUE(s.closed_loop.enabled) << name;
    EXPECT_EQ(s.estimator.navd_mode, NavdMode::kUwb) << name;
    const bool fuzzy = name.find("fuzzy") != std::string::npos;
    EXPECT_NE(s.closed_loop.controller.find(fuzzy ? "--controller fuzzy" : "--lookahead 2.0"),
              std::string::npos)
        << name;
    ASSERT_FALSE(s.paper.empty()) << name;
    EXPECT_EQ(s.paper[0].metric, name.rfind("line", 0) == 0 ? "tracking.from_start_mean_abs_m"
                                                            : "tracking.cross_track_mean_abs_m")
        << name;
    ASSERT_TRUE(s.paper[0].value) << name;
    EXPECT_DOUBLE_EQ(*s.paper[0].value, value) << name;
  }
  const Scenario r = LoadScenario(Dir() + "/seed003_rectangle_fuzzy.yaml");
  ASSERT_FALSE(r.criteria.empty());
  EXPECT_EQ(r.criteria[0].metric, "tracking.cross_track_mean_abs_m");
  ASSERT_TRUE(r.criteria[0].max);
  EXPECT_DOUBLE_EQ(*r.criteria[0].max, 0.144);
}

// closed_loop.pass_to_pass: its keys are read (here a margin changed in the 1 m/s scenario's
// text), an unknown one names its line and field.
TEST(ScenarioFilesTest, PassToPassSettingsAreReadAndCheckedByName) {
  const std::string file = Dir() + "/closed_loop/tractor_autosteer_p2p_1p0.yaml";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string yaml = text.str();
  const Scenario s = ParseScenario(yaml, file);
  EXPECT_DOUBLE_EQ(s.closed_loop.pass_to_pass.window_s, 900);
  std::string changed = yaml;
  const std::size_t at = changed.find("margin_m: 10");
  ASSERT_NE(at, std::string::npos);
  changed.replace(at, 12, "margin_m: 12.5");
  EXPECT_DOUBLE_EQ(ParseScenario(changed, file).closed_loop.pass_to_pass.margin_m, 12.5);
  std::string bad = yaml;
  bad.replace(bad.find("margin_m: 10"), 12, "margin: 10");
  try {
    ParseScenario(bad, file);
    FAIL() << "an unknown key of closed_loop.pass_to_pass was accepted";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), "closed_loop.pass_to_pass.margin") << e.what();
  }
}

}  // namespace
}  // namespace hil::harness

// The suite's side-by-side report: scenario `paper:` and `short:` sections, mean and spread over
// seeds, pass/fail per criterion, per-outage E/N/U maxima, and the Markdown report's columns.
#include "hil/harness/campaign/suite_report.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "process_temp_dir.h"

namespace hil::harness {
namespace {

using nlohmann::json;

constexpr const char* kBase =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n"
    "duration_s: 300\n";

std::string TempFile(const std::string& name, const std::string& text) {
  const auto dir = test::ProcessTempDir("suite_report");
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

void ExpectError(const std::string& text, int line, const std::string& field,
                 const std::string& fragment, bool short_form = false) {
  const std::string path = TempFile("bad.yaml", text);
  try {
    LoadScenario(path, short_form);
    FAIL() << "expected a ScenarioError for:\n" << text;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SuiteReportTest, PaperSectionReadsFiguresAsMappingOrList) {
  Scenario s = LoadScenario(TempFile(
      "one.yaml",
      std::string(kBase) + "paper: {source: P0, metric: horizontal_rmse_m, value: 0.391}\n"));
  ASSERT_EQ(s.paper.size(), 1u);
  EXPECT_EQ(s.paper[0].source, "P0");
  EXPECT_DOUBLE_EQ(*s.paper[0].value, 0.391);
  EXPECT_EQ(s.paper[0].relation, "about");
  s = LoadScenario(TempFile(
      "two.yaml", std::string(kBase) +
                      "paper:\n"
                      "  - {source: P3, metric: max_horizontal_error_m, finding: diverges}\n"
                      "  - {source: P4, metric: outage_max_enu_error_m, value: 0.11, relation: "
                      "below, note: n}\n"));
  ASSERT_EQ(s.paper.size(), 2u);
  EXPECT_FALSE(s.paper[0].value);
  EXPECT_EQ(s.paper[0].finding, "diverges");
  EXPECT_EQ(s.paper[1].relation, "below");
  EXPECT_EQ(s.paper[1].note, "n");
}

TEST(SuiteReportTest, PaperSectionErrorsNameLineAndField) {
  ExpectError(std::string(kBase) + "paper:\n  - {source: P, metric: rmse, value: 1}\n", 5,
              "paper[0].metric", "unknown metric 'rmse'");
  ExpectError(std::string(kBase) + "paper:\n  - {source: P, metric: cep95_m}\n", 5, "paper[0]",
              "needs a 'value' or a 'finding'");
  ExpectError(
      std::string(kBase) + "paper:\n  - {source: P, metric: cep95_m, value: 1, relation: under}\n",
      5, "paper[0].relation", "under");
  ExpectError(std::string(kBase) + "paper:\n  - {source: P, metric: cep95_m, valeu: 1}\n", 5,
              "paper[0].valeu", "did you mean 'value'");
}

TEST(SuiteReportTest, ShortFormReplacesTopLevelKeysOnlyWhenAsked) {
  const std::string text =
      std::string(kBase) +
      "faults:\n  - {kind: gnss_outage, start_s: 200, end_s: 210}\n"
      "short:\n  duration_s: 60\n  faults:\n    - {kind: gnss_outage, start_s: 30, end_s: 40}\n";
  const std::string path = TempFile("short.yaml", text);
  const Scenario full = LoadScenario(path);
  EXPECT_DOUBLE_EQ(full.duration_s, 300);
  EXPECT_TRUE(full.has_short_form);
  EXPECT_FALSE(full.short_form);
  const Scenario quick = LoadScenario(path, true);
  EXPECT_DOUBLE_EQ(quick.duration_s, 60);
  EXPECT_TRUE(quick.short_form);
  ASSERT_EQ(quick.faults.faults.size(), 1u);
  EXPECT_DOUBLE_EQ(ToSeconds(quick.faults.faults[0].start), 30.0);
  // unknown or forbidden keys in short:, and a value the short form makes invalid, name their line
  ExpectError(std::string(kBase) + "short:\n  duraton_s: 60\n", 5, "short.duraton_s",
              "did you mean 'duration_s'");
  ExpectError(std::string(kBase) + "short:\n  name: x\n", 5, "short.name", "unknown key");
  ExpectError(std::string(kBase) +
                  "short:\n  duration_s: 60\n  faults:\n    - {kind: gnss_outage, start_s: 50, "
                  "end_s: 70}\n",
              7, "faults[0].end_s", "", true);
  // a file without short: runs whole in short mode
  EXPECT_FALSE(LoadScenario(TempFile("plain.yaml", kBase), true).short_form);
}

TEST(SuiteReportTest, SpreadIsMeanSampleStdMinMax) {
  const json s = SpreadOf({json(1.0), json(nullptr), json(3.0), json(2.0)});
  EXPECT_EQ(s["n"].get<int>(), 3);
  EXPECT_DOUBLE_EQ(s["mean"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(s["std"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["min"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(s["max"].get<double>(), 3.0);
  EXPECT_EQ(SpreadOf({json(nullptr)})["n"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(SpreadOf({json(0.5)})["std"].get<double>(), 0.0);
}

json FakeRun(const std::string& file, int seed, bool pass, double rmse, double base, double east) {
  json r{{"scenario_file", file},
         {"seed", seed},
         {"pass", pass},
         {"exit_code", pass ? 0 : 1},
         {"run_dir", "x-seed" + std::to_string(seed)}};
  r["metric_table"] = {{"horizontal_rmse_m", rmse}, {"outage_max_enu_error_m", east}};
  r["baseline_table"] = {{"horizontal_rmse_m", base}};
  r["criteria"] = json::array({json{{"name", "horizontal_rmse_m <= 0.3"},
                                    {"threshold", 0.3},
                                    {"value", rmse},
                                    {"pass", rmse <= 0.3}}});
  r["outages"] = json::array({json{{"start_s", 10.0},
                                   {"end_s", 20.0},
                                   {"max_east_error_m", east},
                                   {"max_north_error_m", 0.01},
                                   {"max_up_error_m", 0.02},
                                   {"max_horizontal_error_m", east},
                                   {"reconvergence_time_s", 1.0}}});
  return r;
}

TEST(SuiteReportTest, SummaryPutsPapersFiguresBesideTheSeedsSpread) {
  SuiteScenarioInfo a;
  a.file = "dir/a.yaml";
  a.scenario = LoadScenario(
      TempFile("a.yaml", std::string(kBase) +
                             "paper: {source: Paper 000, metric: horizontal_rmse_m, value: 0.313}\n"
                             "criteria:\n  - {metric: horizontal_rmse_m, max: 0.3}\n"));
  SuiteScenarioInfo bad;
  bad.file = "dir/b.yaml";
  bad.error = "b.yaml:3: gnss.baud: out of range";
  const json runs = json::array({FakeRun("dir/a.yaml", 1, true, 0.25, 0.35, 0.05),
                                 FakeRun("dir/a.yaml", 2, false, 0.35, 0.40, 0.09),
                                 json{{"scenario_file", "dir/b.yaml"},
                                      {"pass", false},
                                      {"exit_code", 2},
                                      {"error", "invalid"}}});
  const json s = SummariseScenarios({a, bad}, runs);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0]["runs"].get<int>(), 2);
  EXPECT_EQ(s[0]["passed"].get<int>(), 1);
  EXPECT_FALSE(s[0]["pass"].get<bool>());
  ASSERT_EQ(s[0]["paper"].size(), 1u);
  EXPECT_DOUBLE_EQ(s[0]["paper"][0]["value"].get<double>(), 0.313);
  EXPECT_DOUBLE_EQ(s[0]["paper"][0]["ours"]["mean"].get<double>(), 0.30);
  EXPECT_DOUBLE_EQ(s[0]["paper"][0]["raw_gnss"]["max"].get<double>(), 0.40);
  ASSERT_EQ(s[0]["criteria"].size(), 1u);
  EXPECT_EQ(s[0]["criteria"][0]["passed"].get<int>(), 1);
  EXPECT_FALSE(s[0]["criteria"][0]["pass"].get<bool>());  // failed in one seed
  EXPECT_EQ(s[0]["criteria"][0]["metric"], "horizontal_rmse_m");
  ASSERT_EQ(s[0]["outages"].size(), 1u);
  EXPECT_DOUBLE_EQ(s[0]["outages"][0]["max_east_error_m"]["max"].get<double>(), 0.09);
  EXPECT_EQ(s[1]["error"], bad.error);
  EXPECT_FALSE(s[1]["pass"].get<bool>());

  json summary{{"scenario_dir", "dir"}, {"seeds", 2},    {"passed", 1},    {"failed", 1},
               {"invalid", 1},          {"pass", false}, {"scenarios", s}, {"runs", runs}};
  const std::string md = SuiteMarkdown(summary);
  EXPECT_NE(
      md.find("| scenario | source | metric | paper | ours | raw GNSS (one receiver) | note |"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("| t | Paper 000 | `horizontal_rmse_m` | 31.3 cm | 30.0 cm ± 7.1 cm (25.0 cm – "
                    "35.0 cm, 2 seeds) | 37.5 cm"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("max east"), std::string::npos);
  EXPECT_NE(md.find("| t | horizontal_rmse_m <= 0.3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1/2 | **FAIL** |"), std::string::npos) << md;
  EXPECT_NE(md.find("**INVALID**"), std::string::npos);
}

}  // namespace
}  // namespace hil::harness

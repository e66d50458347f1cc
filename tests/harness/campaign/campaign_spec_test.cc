// Campaign files: globs, seeds, sweeps (cartesian, zipped), criteria, and strict errors that name
// the file, the line and the field; the plan's run ids and its round-robin shards.
#include "hil/harness/campaign/campaign_spec.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "hil/harness/campaign/campaign_plan.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScenario =
    "name: s\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n"
    "duration_s: 60\n"
    "gnss: {baud: 9600}\n";

class CampaignSpecTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hil_campaign_spec_" + std::to_string(getpid()));
    fs::create_directories(dir_ / "sc");
    std::ofstream(dir_ / "sc/b_two.yaml") << kScenario;
    std::ofstream(dir_ / "sc/a_one.yaml") << kScenario;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& text) {
    const std::string p = (dir_ / "c.yaml").string();
    std::ofstream(p) << text;
    return p;
  }
  void ExpectError(const std::string& text, int line, const std::string& field,
                   const std::string& fragment) {
    const std::string path = Write(text);
    try {
      ReadCampaignFile(path);
      FAIL() << "expected a ScenarioError for:\n" << text;
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

TEST_F(CampaignSpecTest, ReadsGlobsSeedsSweepsAndCriteria) {
  const CampaignSpec s = ReadCampaignFile(
      Write("name: mc\n"
            "scenarios: [sc/*.yaml]\n"
            "seeds: {from: 3, count: 4}\n"
            "sweep:\n"
            "  fields:\n"
            "    - {field: gnss.baud, values: [9600, 38400]}\n"
            "    - {field: duration_s, values: [30, 40, 50]}\n"
            "criteria:\n"
            "  - {metric: horizontal_rmse_m, stat: p95, max: 0.6, scenarios: 'a_*'}\n"
            "  - {pass_fraction: 0.75}\n"
            "run: {mode: scaled, speed: 5}\n"));
  ASSERT_EQ(s.scenario_files.size(), 2u);
  EXPECT_EQ(fs::path(s.scenario_files[0]).filename(), "a_one.yaml");  // sorted
  EXPECT_EQ(s.seeds, (std::vector<std::uint64_t>{3, 4, 5, 6}));
  ASSERT_EQ(s.criteria.size(), 2u);
  EXPECT_EQ(s.criteria[0].name, "p95 of horizontal_rmse_m <= 0.6");
  EXPECT_EQ(s.criteria[1].kind, "pass_fraction");
  EXPECT_DOUBLE_EQ(*s.criteria[1].min, 0.75);
  EXPECT_EQ(s.run_args, (std::vector<std::string>{"--mode", "scaled", "--speed", "5"}));
  const auto points = SweepPoints(s);
  ASSERT_EQ(points.size(), 6u);  // cartesian: the last field varies fastest
  EXPECT_EQ(points[1][0].value, "9600");
  EXPECT_EQ(points[1][1].value, "40");
  EXPECT_EQ(points[3][0].value, "38400");
  const CampaignPlan plan = PlanCampaign(s);
  EXPECT_EQ(plan.groups.size(), 12u);
  ASSERT_EQ(plan.runs.size(), 48u);
  EXPECT_EQ(plan.runs[0].id, "a_one__p0-seed3");
  EXPECT_EQ(plan.runs[47].id, "b_two__p5-seed6");
  // the plan survives campaign.json
  const CampaignPlan back = PlanFromJson(PlanToJson(plan));
  EXPECT_EQ(PlanToJson(back), PlanToJson(plan));
  EXPECT_EQ(back.runs.size(), plan.runs.size());
}

TEST_F(CampaignSpecTest, ZipPairsValuesAndShardsCoverEveryRunOnce) {
  const CampaignSpec s =
      ReadCampaignFile(Write("name: z\nscenarios: sc/a_one.yaml\nseeds: [1, 2, 7]\n"
                             "sweep:\n  combine: zip\n  fields:\n"
                             "    - {field: gnss.baud, values: [9600, 38400]}\n"
                             "    - {field: duration_s, values: [30, 40]}\n"));
  const auto points = SweepPoints(s);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1][0].value, "38400");
  EXPECT_EQ(points[1][1].value, "40");
  const CampaignPlan plan = PlanCampaign(s);
  ASSERT_EQ(plan.runs.size(), 6u);
  std::multiset<std::size_t> seen;
  for (int k = 1; k <= 4; ++k) {
    for (std::size_t i : ShardRuns(plan, k, 4)) {
      seen.insert(i);
      EXPECT_EQ(ShardOfRun(i, 4), k);
    }
  }
  EXPECT_EQ(seen.size(), 6u);
  EXPECT_EQ(std::set<std::size_t>(seen.begin(), seen.end()).size(), 6u);
  EXPECT_EQ(ShardRuns(plan, 1, 4), (std::vector<std::size_t>{0, 4}));
}

TEST_F(CampaignSpecTest, ErrorsNameFileLineAndField) {
  ExpectError("name: x\nscenarios: [sc/*.yaml]\nseeds: {from: 1, cuont: 3}\n", 3, "seeds.cuont",
              "did you mean 'count'");
  ExpectError("name: x\nscenarios: [sc/none_*.yaml]\n", 2, "scenarios[0]", "matches no scenario");
  ExpectError("name: x\nscenarios: [sc/*.yaml]\nseeds: [1, 1]\n", 3, "seeds", "listed twice");
  ExpectError("name: x\nscenarios: [sc/*.yaml]\ncriteria:\n  - {metric: rmse, max: 1}\n", 4,
              "criteria[0].metric", "unknown metric 'rmse'");
  ExpectError(
      "name: x\nscenarios: [sc/*.yaml]\ncriteria:\n  - {metric: cep95_m, stat: p99, "
      "max: 1}\n",
      4, "criteria[0].stat", "p99");
  ExpectError(
      "name: x\nscenarios: [sc/*.yaml]\nsweep:\n  combine: zip\n  fields:\n"
      "    - {field: gnss.baud, values: [9600, 38400]}\n"
      "    - {field: duration_s, values: [30]}\n",
      7, "sweep.fields[1].values", "as many values");
  // a value the scenario rejects is reported at the value's line in the campaign file
  ExpectError(
      "name: x\nscenarios: [sc/a_one.yaml]\nsweep:\n  fields:\n"
      "    - field: duration_s\n      values:\n        - 30\n        - -5\n",
      8, "sweep.fields[0].values[1]", "duration_s");
  ExpectError(
      "name: x\nscenarios: [sc/a_one.yaml]\nsweep:\n  fields:\n"
      "    - {field: gnss.nosuch.deeper, values: [1]}\n",
      5, "sweep.fields[0].values[0]", "no 'gnss.nosuch'");
  ExpectError("name: has space\nscenarios: [sc/*.yaml]\n", 1, "name", "without spaces");
  ExpectError("name: x\nscenarios: [sc/*.yaml]\nsweeps: {}\n", 3, "sweeps", "did you mean");
}

// A scenario's statistical claim (issue 43): its `statistical:` section gives the seeds and the
// criteria across them (campaign criteria, on this scenario alone); the plan runs that file over
// its own seeds and the others once, and the plan survives campaign.json
TEST_F(CampaignSpecTest, ScenarioStatisticalClaimPlansItsOwnSeeds) {
  const Scenario sc =
      ParseScenario(std::string(kScenario) +
                        "seed: 7\n"
                        "statistical:\n"
                        "  seeds: 20\n"
                        "  criteria:\n"
                        "    - {metric: horizontal_rmse_to_raw, stat: mean, max: 0.65}\n"
                        "    - {metric: horizontal_rmse_to_raw, stat: p95, max: 0.8}\n",
                    "s.yaml");
  EXPECT_EQ(sc.statistical_seeds, 20);
  ASSERT_EQ(sc.statistical_criteria.size(), 2U);
  EXPECT_EQ(sc.statistical_criteria[0].stat, "mean");
  EXPECT_EQ(sc.statistical_criteria[0].scenarios, "s");
  EXPECT_EQ(sc.statistical_criteria[1].name, "p95 of horizontal_rmse_to_raw <= 0.8");
  CampaignSpec spec;
  spec.scenario_files = {"a.yaml", "b.yaml"};
  for (std::uint64_t k = 7; k < 27; ++k) spec.file_seeds["b.yaml"].push_back(k);
  const CampaignPlan plan = PlanCampaign(spec);
  ASSERT_EQ(plan.runs.size(), 21U);
  EXPECT_EQ(plan.runs[0].id, "a");
  EXPECT_FALSE(plan.runs[0].seed);
  EXPECT_EQ(plan.runs[1].id, "b-seed7");
  EXPECT_EQ(plan.runs[20].id, "b-seed26");
  EXPECT_EQ(PlanFromJson(PlanToJson(plan)).runs.size(), 21U);
  EXPECT_THROW(ParseScenario(std::string(kScenario) +
                                 "statistical: {seeds: 20, criteria: [{metric: x, max: 1}]}\n",
                             "s.yaml"),
               ScenarioError);
}

}  // namespace
}  // namespace hil::harness

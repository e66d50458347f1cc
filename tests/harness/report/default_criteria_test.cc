// The default criteria (default_criteria.h): read from a scenario, chosen per run, evaluated.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/dut/estimate_reader.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/report/report.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

constexpr const char* kMinimal =
    "name: t\n"
    "origin: {lat_deg: 35.0, lon_deg: 50.0}\n";

// A report with `n` solutions and raw fixes of the given RMSE, and a mean NEES when given.
RunReport Report(double est_rmse_m, double raw_rmse_m, std::optional<double> nees_h) {
  RunReport r;
  r.metrics.samples = 100;
  r.metrics.horizontal_rmse_m = est_rmse_m;
  r.baselines.samples = 10;
  r.baselines.horizontal_rmse_m = raw_rmse_m;
  if (nees_h) {
    r.metrics.nees_mean = *nees_h + 1.0;
    r.metrics.nees_horizontal_mean = nees_h;
    r.metrics.nees_vertical_mean = 1.0;
  }
  return r;
}

const DefaultCriterionStatus& StatusOf(const std::vector<DefaultCriterionStatus>& all,
                                       const std::string& key) {
  const auto it = std::find_if(all.begin(), all.end(),
                               [&](const DefaultCriterionStatus& s) { return s.key == key; });
  EXPECT_NE(it, all.end()) << key;
  return *it;
}

std::vector<CriterionResult> Judge(const Scenario& s, RunReport& r) {
  std::vector<Criterion> all = s.criteria;
  const std::vector<Criterion> d = DefaultCriteriaFor(s, r, r.default_criteria);
  all.insert(all.end(), d.begin(), d.end());
  return EvaluateCriteria(all, RunMetricTable(r), AccuracyTable(r.baselines));
}

const CriterionResult* Find(const std::vector<CriterionResult>& c, const std::string& key) {
  for (const auto& x : c) {
    if (x.default_key == key) return &x;
  }
  return nullptr;
}

// A diverged estimate (55 m against 0.3 m raw) with an over-confident σ passed a scenario with no
// criteria; by default it fails, each default naming itself
TEST(DefaultCriteriaTest, DivergedEstimateFailsWithoutCriteria) {
  const Scenario s = ParseScenario(kMinimal, "s.yaml");
  RunReport r = Report(55.0, 0.3, 87008.0);
  const auto results = Judge(s, r);
  const CriterionResult* raw = Find(results, "fused_vs_raw");
  ASSERT_NE(raw, nullptr);
  EXPECT_FALSE(raw->pass);
  EXPECT_NEAR(raw->threshold, 0.36, 1e-12);
  EXPECT_NE(raw->name.find("default fused_vs_raw"), std::string::npos) << raw->name;
  const CriterionResult* nees = Find(results, "nees_horizontal");
  ASSERT_NE(nees, nullptr);
  EXPECT_FALSE(nees->pass);
  EXPECT_EQ(StatusOf(r.default_criteria, "controller_commanding").status, "not applicable");
}

TEST(DefaultCriteriaTest, ConsistentEstimateBetterThanRawPasses) {
  const Scenario s = ParseScenario(kMinimal, "s.yaml");
  RunReport r = Report(0.2, 0.3, 2.1);
  r.timing.missing_fraction = 0.0;
  for (const auto& c : Judge(s, r)) EXPECT_TRUE(c.pass) << c.name;
}

TEST(DefaultCriteriaTest, ScenarioRelaxesTurnsOffOrSupersedes) {
  const Scenario s = ParseScenario(std::string(kMinimal) +
                                       "default_criteria: {fused_vs_raw: 2.0, nees_vertical: off}\n"
                                       "criteria:\n"
                                       "  - {metric: nees_horizontal_mean, max: 50}\n",
                                   "s.yaml");
  RunReport r = Report(0.5, 0.3, 40.0);
  r.timing.missing_fraction = 0.0;
  const auto results = Judge(s, r);
  EXPECT_EQ(StatusOf(r.default_criteria, "fused_vs_raw").status, "relaxed");
  EXPECT_TRUE(Find(results, "fused_vs_raw")->pass);  // 0.5 <= 2.0 x 0.3
  EXPECT_EQ(StatusOf(r.default_criteria, "nees_vertical").status, "off");
  EXPECT_EQ(Find(results, "nees_vertical"), nullptr);
  EXPECT_EQ(StatusOf(r.default_criteria, "nees_horizontal").status, "superseded");
  EXPECT_EQ(Find(results, "nees_horizontal"), nullptr);
  for (const auto& c : results) EXPECT_TRUE(c.pass) << c.name;
}

TEST(DefaultCriteriaTest, NotApplicableWithoutFixesOrSigma) {
  const Scenario s = ParseScenario(kMinimal, "s.yaml");
  RunReport r = Report(0.5, 0.3, std::nullopt);
  r.baselines.samples = 0;
  const auto results = Judge(s, r);
  EXPECT_EQ(StatusOf(r.default_criteria, "fused_vs_raw").status, "not applicable");
  EXPECT_EQ(StatusOf(r.default_criteria, "nees_horizontal").status, "not applicable");
  EXPECT_EQ(StatusOf(r.default_criteria, "completeness").status, "judged");
  EXPECT_NE(Find(results, "completeness"), nullptr);
}

// A scenario that stops the controller on purpose is not judged on its missing commands
TEST(DefaultCriteriaTest, ControllerCommandingNotJudgedWhenTheScenarioStopsIt) {
  Scenario s = ParseScenario(kMinimal, "s.yaml");
  s.closed_loop.enabled = true;
  RunReport r = Report(0.2, 0.3, 2.0);
  DefaultCriteriaFor(s, r, r.default_criteria);
  EXPECT_EQ(StatusOf(r.default_criteria, "controller_commanding").status, "judged");
  Fault stop;
  stop.kind = FaultKind::kControllerStop;
  s.faults.faults.push_back(stop);
  DefaultCriteriaFor(s, r, r.default_criteria);
  EXPECT_EQ(StatusOf(r.default_criteria, "controller_commanding").status, "not applicable");
}

TEST(DefaultCriteriaTest, BadSettingNamesLineAndField) {
  try {
    ParseScenario(std::string(kMinimal) + "default_criteria: {fused_vs_rwa: 2}\n", "s.yaml");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("fused_vs_raw"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      ParseScenario(std::string(kMinimal) + "default_criteria: {completeness: -1}\n", "s.yaml"),
      ScenarioError);
}

// The mean NEES split by dimension: 2 DOF east/north, 1 DOF up
TEST(DefaultCriteriaTest, NeesSplitByDimension) {
  std::vector<ErrorSample> e(2);
  e[0].err_enu_m = {1, 1, 1};
  e[0].nees = 3, e[0].nees_horizontal = 2, e[0].nees_vertical = 1;
  e[1].err_enu_m = {1, 1, 1};
  e[1].nees = 12, e[1].nees_horizontal = 8, e[1].nees_vertical = 4;
  const AccuracyMetrics m = ComputeAccuracy(e);
  EXPECT_DOUBLE_EQ(*m.nees_mean, 7.5);
  EXPECT_DOUBLE_EQ(*m.nees_horizontal_mean, 5.0);
  EXPECT_DOUBLE_EQ(*m.nees_vertical_mean, 2.5);
}

// A malformed solution line: the message says why (the first field wrong)
TEST(DefaultCriteriaTest, WhyAJsonLineIsNoSolution) {
  auto r = MakeEstimateReader(EstimatorOutput::kJsonStdout, UnixTime{});
  EXPECT_EQ(r->WhyNotASolution("navd: starting"), "not JSON");
  EXPECT_EQ(r->WhyNotASolution(R"({"lat_deg":1})"), "no \"lon_deg\"");
  EXPECT_EQ(r->WhyNotASolution(R"({"lat_deg":1,"lon_deg":"2"})"), "\"lon_deg\" is not a number");
  EXPECT_EQ(r->WhyNotASolution(R"({"lat_deg":1,"lon_deg":2})"),
            "neither \"tov_unix_ns\" nor \"tov_utc_s\"");
  EXPECT_EQ(r->WhyNotASolution(R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":1.5})"),
            "\"tov_unix_ns\" is not an integer (UTC nanoseconds)");
}

}  // namespace
}  // namespace hil::harness

// Closed-loop faults end to end (issue 16 item 7): the short forms of the fault scenarios in
// vectors/scenarios/closed_loop/ pass their criteria, and report.json says what each fault did
// (closed_loop figures, the fault's injection record, its path deviation in tracking.faults).
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hil::test {
namespace {

nlohmann::json RunScenario(const std::string& name) {
  TempDir dir("e2e_cl_" + name);
  const CommandResult r = RunCommand(BinDir() + "/hil run " + SourceDir() +
                                     "/vectors/scenarios/closed_loop/diff_drive_" + name +
                                     ".yaml --short --no-html --out " + dir / "r");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  return nlohmann::json::parse(ReadFile(dir / "r/report.json"));
}

// The scenario's one fault: its injection record and its tracking.faults entry.
void ExpectFault(const nlohmann::json& rep, const std::string& kind, int count) {
  ASSERT_EQ(rep["fault_injections"].size(), 1U);
  EXPECT_EQ(rep["fault_injections"][0]["kind"], kind);
  EXPECT_EQ(rep["fault_injections"][0]["count"].get<int>(), count) << rep["fault_injections"];
  ASSERT_EQ(rep["tracking"]["faults"].size(), 1U);
  EXPECT_EQ(rep["tracking"]["faults"][0]["kind"], kind);
  EXPECT_GT(rep["tracking"]["faults"][0]["samples"].get<int>(), 50);
}

TEST(ClosedLoopFaultsE2eTest, CommandLatencyAndJitterDelayEveryCommandInTheWindow) {
  const auto rep = RunScenario("command_latency");
  EXPECT_TRUE(rep["pass"].get<bool>()) << rep["criteria"].dump(2);
  const auto& cl = rep["closed_loop"];
  EXPECT_EQ(cl["delayed_commands"].get<int>(), 300) << "10 Hz from 10 s to 40 s";
  // 150 ms plus a uniform draw in [0, 100 ms): a mean near 200 ms, never 250 ms or more
  EXPECT_NEAR(cl["added_latency_mean_s"].get<double>(), 0.2, 0.01);
  EXPECT_LT(cl["added_latency_max_s"].get<double>(), 0.25);
  EXPECT_GT(cl["added_latency_max_s"].get<double>(), 0.24);
  ExpectFault(rep, "command_latency", 300);
}

TEST(ClosedLoopFaultsE2eTest, SaturationIsReportedAsTimeSaturated) {
  const auto rep = RunScenario("saturation");
  EXPECT_TRUE(rep["pass"].get<bool>()) << rep["criteria"].dump(2);
  EXPECT_NEAR(rep["closed_loop"]["saturated_time_s"].get<double>(), 10.0, 1e-6);
  EXPECT_EQ(rep["closed_loop"]["saturated_commands"].get<int>(), 100);
  ExpectFault(rep, "actuator_saturation", 100);
}

TEST(ClosedLoopFaultsE2eTest, AStuckActuatorHoldsForItsDuration) {
  const auto rep = RunScenario("stuck_actuator");
  EXPECT_TRUE(rep["pass"].get<bool>()) << rep["criteria"].dump(2);
  EXPECT_NEAR(rep["closed_loop"]["stuck_time_s"].get<double>(), 3.0, 1e-6);
  EXPECT_EQ(rep["closed_loop"]["commands_not_followed"].get<int>(), 30);
  ExpectFault(rep, "actuator_stuck", 30);
}

TEST(ClosedLoopFaultsE2eTest, AGnssGlitchShowsUpAsPathDeviation) {
  const auto rep = RunScenario("gnss_glitch");
  EXPECT_TRUE(rep["pass"].get<bool>()) << rep["criteria"].dump(2);
  const auto& f = rep["tracking"]["faults"][0];
  // the fixes jump 0.3 m north (left); the controller puts the estimate back on the line and the
  // truth to the right of it, about as far
  EXPECT_GT(f["max_deviation_m"].get<double>(), 0.2) << f.dump(2);
  EXPECT_LT(f["cross_track_at_max_m"].get<double>(), -0.2) << f.dump(2);
  EXPECT_GE(f["max_deviation_s"].get<double>(), 30.0);
  EXPECT_GT(rep["estimator_health"]["counters"]["gnss_rejected"].get<double>(), 0);
}

}  // namespace
}  // namespace hil::test

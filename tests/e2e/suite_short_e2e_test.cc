// The short acceptance suite through the real hil binary, as CI runs it on every commit:
// `hil suite vectors/scenarios --short --seeds 2`. It checks that the side-by-side report is
// complete and correct (every scenario file, the papers' figures beside ours, per-outage E/N/U
// maxima, junit) and that paper 000's GPS-only, IMU-only and three-receiver criteria pass. Criteria
// of scenarios whose estimator accuracy is still being worked on (seed000_gps_imu, seed004_outages)
// and of the variants are reported, not enforced here (README, "The full acceptance suite").
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hil::test {
namespace {

using nlohmann::json;

const json* Scenario(const json& summary, const std::string& name) {
  for (const auto& s : summary["scenarios"]) {
    if (s.value("scenario", "") == name) return &s;
  }
  return nullptr;
}

TEST(SuiteShortE2eTest, ReportPutsPapersBesideOursAndPaper000Passes) {
  TempDir dir("suite_short");
  const std::string scenarios = SourceDir() + "/vectors/scenarios";
  const CommandResult r = RunCommand(BinDir() + "/hil suite " + scenarios +
                                     " --short --seeds 2 -j 2 --out " + dir / "out");
  // 0 all passed, 1 a criterion failed; 2 (an invalid scenario, a run that could not start) is a
  // bug
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.out;
  const json summary = json::parse(ReadFile(dir / "out/summary.json"));
  EXPECT_TRUE(summary["short_form"].get<bool>());
  EXPECT_EQ(summary["invalid"].get<int>(), 0) << r.out;

  // every scenario file of the folder is in the report, each with its two seeds
  std::set<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(scenarios)) {
    if (e.path().extension() == ".yaml") files.insert(e.path().string());
  }
  ASSERT_EQ(summary["scenarios"].size(), files.size());
  for (const auto& s : summary["scenarios"]) {
    EXPECT_EQ(files.count(s["scenario_file"].get<std::string>()), 1u) << s["scenario_file"];
    EXPECT_EQ(s["runs"].get<int>(), 2) << s["scenario"];
    EXPECT_FALSE(s.contains("error")) << s["scenario"] << ": " << s.value("error", "");
    // the papers' scenarios: every criterion computed in every seed (a missing value is a broken
    // run)
    if (s["scenario"].get<std::string>().rfind("seed00", 0) != 0) continue;
    for (const auto& c : s["criteria"]) {
      EXPECT_EQ(c["value"]["n"].get<int>(), 2)
          << s["scenario"] << ": " << c["name"] << " could not be computed";
    }
  }

  // paper 000: one receiver, three receivers, IMU alone pass in both seeds, beside the paper's
  // figures
  for (const char* name : {"seed000_gps_only", "seed000_three_gps", "seed000_imu_only"}) {
    const json* s = Scenario(summary, name);
    ASSERT_NE(s, nullptr) << name;
    EXPECT_TRUE((*s)["pass"].get<bool>()) << name << "\n" << s->dump(1);
    EXPECT_FALSE((*s)["paper"].empty()) << name;
  }
  const json* one = Scenario(summary, "seed000_gps_only");
  const json* three = Scenario(summary, "seed000_three_gps");
  ASSERT_TRUE(one && three);
  EXPECT_DOUBLE_EQ((*one)["paper"][0]["value"].get<double>(), 0.391);
  EXPECT_DOUBLE_EQ((*three)["paper"][0]["value"].get<double>(), 0.313);
  // three receivers beat the first of them alone, in the mean over the seeds
  EXPECT_LT((*three)["paper"][0]["ours"]["mean"].get<double>(),
            (*three)["paper"][0]["raw_gnss"]["mean"].get<double>());

  // paper 000's fused filter and paper 004: the figures are there, whatever the verdict
  const json* fused = Scenario(summary, "seed000_gps_imu");
  ASSERT_NE(fused, nullptr);
  EXPECT_DOUBLE_EQ((*fused)["paper"][0]["value"].get<double>(), 0.234);
  EXPECT_EQ((*fused)["paper"][0]["ours"]["n"].get<int>(), 2);
  const json* p004 = Scenario(summary, "seed004_outages");
  ASSERT_NE(p004, nullptr);
  ASSERT_FALSE((*p004)["outages"].empty()) << "the short form keeps outages inside the run";
  for (const auto& o : (*p004)["outages"]) {
    for (const char* axis :
         {"max_east_error_m", "max_north_error_m", "max_up_error_m", "max_horizontal_error_m"}) {
      EXPECT_EQ(o[axis]["n"].get<int>(), 2) << axis;
    }
  }

  // the Markdown report has the papers' column and the figures
  const std::string md = ReadFile(dir / "out/report.md");
  EXPECT_NE(
      md.find("| scenario | source | metric | paper | ours | raw GNSS (one receiver) | note |"),
      std::string::npos);
  for (const char* figure :
       {"| 39.1 cm |", "| 31.3 cm |", "diverges", "| 23.4 cm |", "| < 11.0 cm |", "max east"}) {
    EXPECT_NE(md.find(figure), std::string::npos) << figure << "\n" << md;
  }
  // junit: one testsuite per run, and one for the criteria across seeds (seed000_gps_imu's
  // statistical claim, judged here over the two seeds given)
  const std::string junit = ReadFile(dir / "out/junit.xml");
  std::size_t suites = 0;
  for (std::size_t p = 0; (p = junit.find("<testsuite ", p)) != std::string::npos; ++p) ++suites;
  EXPECT_EQ(suites, 2 * files.size() + 1);
  ASSERT_EQ(summary["criteria"].size(), 3u) << summary["criteria"].dump(1);
  EXPECT_EQ(summary["criteria"][0]["scenarios"], "seed000_gps_imu");
  EXPECT_EQ(summary["criteria"][0]["groups"][0]["n"].get<int>(), 2);
}

}  // namespace
}  // namespace hil::test

// The ISO 12188-2 style evaluation end to end (issue 44, item 4): hil runs the short form of
// vectors/scenarios/closed_loop/tractor_autosteer_p2p_5p0.yaml (the tractor auto-steered at 5 m/s
// over ISOBUS on SLCAN, 70 s: rows 2, 3 and the start of 4 after the evaluation's start), and the
// report's `pass_to_pass` object holds the adjacent passes with figures that agree with each other
// and with the absolute tracking: the nearest sample is never nearer than the interpolated track,
// and two passes each within e of their rows are within 2e of their spacing.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hil::test {
namespace {

TEST(PassToPassE2eTest, ShortTractorRunReportsConsistentPassToPassFigures) {
  TempDir dir("e2e_pass_to_pass");
  const CommandResult r = RunCommand(
      BinDir() + "/hil run " + SourceDir() +
      "/vectors/scenarios/closed_loop/tractor_autosteer_p2p_5p0.yaml --short --out " + dir / "r");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto rep = nlohmann::json::parse(ReadFile(dir / "r/report.json"));
  ASSERT_TRUE(rep.contains("pass_to_pass")) << rep.dump(2);
  const auto& p = rep["pass_to_pass"];
  EXPECT_DOUBLE_EQ(p["window_s"].get<double>(), 900);
  EXPECT_GE(p["window_start_s"].get<double>(), 25.0);
  EXPECT_LE(p["window_end_s"].get<double>(), 70.0);
  EXPECT_GE(p["passes"].get<int>(), 3) << p.dump(2);
  ASSERT_GE(p["pairs"].size(), 2u) << p.dump(2);
  std::size_t samples = 0;
  for (const auto& pair : p["pairs"]) {
    EXPECT_NEAR(pair["spacing_m"].get<double>(), 7.5, 1e-6);
    EXPECT_EQ(pair["to_segment"].get<int>(), pair["from_segment"].get<int>() + 2) << "a turn";
    const auto& ip = pair["interpolated"];
    const auto& np = pair["nearest_point"];
    ASSERT_GT(ip["samples"].get<int>(), 0);
    EXPECT_EQ(np["samples"], ip["samples"]);
    EXPECT_GE(np["mean_m"].get<double>(), ip["mean_m"].get<double>() - 1e-12);
    samples += ip["samples"].get<std::size_t>();
  }
  const auto& ip = p["interpolated"];
  EXPECT_EQ(ip["samples"].get<std::size_t>(), samples);
  EXPECT_LE(ip["mean_abs_m"].get<double>(), ip["max_abs_m"].get<double>());
  EXPECT_LE(ip["p95_abs_m"].get<double>(), ip["max_abs_m"].get<double>());
  // truth every 0.1 s at 5 m/s: samples 0.5 m apart, the nearest at most 0.25 m along the pass:
  // sqrt(7.5² + 0.25²) − 7.5 = 4.2 mm more than the interpolation (1 cm with the speed's wander)
  EXPECT_LE(p["method_difference_max_m"].get<double>(), 0.01);
  const auto& abs = p["absolute"];
  EXPECT_GE(abs["samples"].get<std::size_t>(), samples);
  EXPECT_LE(ip["max_abs_m"].get<double>(), 2 * abs["max_abs_m"].get<double>() + 0.01) << p.dump(2);
  // its figures are criteria: the scenario's pass_to_pass.pairs >= 1
  bool judged = false;
  for (const auto& c : rep["criteria"]) {
    if (c["name"].get<std::string>().find("pass_to_pass.pairs") == std::string::npos) continue;
    judged = true;
    EXPECT_DOUBLE_EQ(c["value"].get<double>(), static_cast<double>(p["pairs"].size()));
  }
  EXPECT_TRUE(judged) << rep["criteria"].dump(2);
  EXPECT_NE(ReadFile(dir / "r/report.html").find("Pass-to-pass (ISO 12188-2 style)"),
            std::string::npos);
}

}  // namespace
}  // namespace hil::test

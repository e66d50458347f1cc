// The campaign report (campaign_report.h): the raw GNSS fixes' figures beside the estimate's per
// group, a link from every run to its own report, and CDF plots whose groups differ in scale by
// ten times or more drawn on a log axis (on one linear axis the small group was a vertical line
// against the left edge).
#include "hil/harness/campaign/campaign_report.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

using nlohmann::json;

json Stats(double mean, double p95) {
  return {{"n", 2}, {"mean", mean}, {"p50", mean}, {"p95", p95}, {"max", p95}};
}

json Run(const std::string& id, const std::string& group, int exit_code, double rmse) {
  return {{"id", id},
          {"group", group},
          {"run_dir", "runs/" + id},
          {"exit_code", exit_code},
          {"criteria",
           {{{"name", "horizontal_rmse_m <= 0.5"}, {"pass", exit_code == 0}, {"value", rmse}}}},
          {"metric_table", {{"horizontal_rmse_m", rmse}}}};
}

json Summary(double scale_b) {
  json s{{"title", "t"},     {"runs_planned", 4},
         {"complete", true}, {"passed", 3},
         {"failed", 1},      {"invalid", 0},
         {"pass", false},    {"report_metrics", {"horizontal_rmse_m"}}};
  s["runs"] = {Run("a-seed1", "a", 0, 0.1), Run("a-seed2", "a", 0, 0.12),
               Run("b-seed1", "b", 0, 0.1 * scale_b), Run("b-seed2", "b", 1, 0.13 * scale_b)};
  s["groups"] = {{{"id", "a"},
                  {"metrics", {{"horizontal_rmse_m", Stats(0.11, 0.12)}}},
                  {"baselines", {{"horizontal_rmse_m", Stats(0.22, 0.25)}}}},
                 {{"id", "b"}, {"metrics", {{"horizontal_rmse_m", Stats(0.115, 0.13)}}}}};
  return s;
}

TEST(CampaignReportTest, MetricsSitBesideTheRawFixesOfTheSameRuns) {
  const std::string md = CampaignMarkdown(Summary(1));
  EXPECT_NE(md.find("| raw GNSS mean | raw GNSS p95 | mean fused/raw |"), std::string::npos) << md;
  EXPECT_NE(
      md.find("| a | horizontal_rmse_m | 2 | 0.11 | 0.11 | 0.12 | 0.12 | 0.22 | 0.25 | 0.5 |"),
      std::string::npos)
      << md;
  // a group whose runs have no raw fixes says so
  EXPECT_NE(
      md.find("| b | horizontal_rmse_m | 2 | 0.115 | 0.115 | 0.13 | 0.13 | n/a | n/a | n/a |"),
      std::string::npos)
      << md;
}

TEST(CampaignReportTest, EveryRunLinksToItsOwnReport) {
  const json s = Summary(1);
  const std::string md = CampaignMarkdown(s), html = CampaignHtml(s);
  for (const char* id : {"a-seed1", "a-seed2", "b-seed1", "b-seed2"}) {
    const std::string link = std::string("runs/") + id + "/report.html";
    EXPECT_NE(md.find("[" + std::string(id) + "](" + link + ")"), std::string::npos) << id;
    EXPECT_NE(html.find("<a href=\"" + link + "\">" + id + "</a>"), std::string::npos) << id;
  }
  EXPECT_NE(
      md.find("| [b-seed2](runs/b-seed2/report.html) | b | FAIL | horizontal_rmse_m <= 0.5 |"),
      std::string::npos)
      << md;
}

// A sweep's groups are "a__p0", "a__p1": the report says which field values each one ran with,
// in a table of the groups and in the CDF plots' legends.
TEST(CampaignReportTest, GroupsSayTheirSweepPoint) {
  json s = Summary(1);
  s["groups"][0]["scenario_file"] = "vectors/scenarios/a.yaml";
  s["groups"][0]["runs"] = 2;
  s["groups"][0]["passed"] = 2;
  s["groups"][0]["settings"] = {{{"field", "gnss.errors.horizontal_sigma_m"}, {"value", "0.15"}},
                                {{"field", "gnss.rate_hz"}, {"value", "5"}}};
  const std::string html = CampaignHtml(s);
  EXPECT_NE(html.find("<h2>Groups</h2>"), std::string::npos) << html;
  EXPECT_NE(html.find("<tr><td>a</td><td>vectors/scenarios/a.yaml</td><td>"
                      "gnss.errors.horizontal_sigma_m = 0.15, gnss.rate_hz = 5</td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td>b</td><td></td><td>the scenario as written</td>"), std::string::npos);
  EXPECT_NE(CdfSvg(s, "horizontal_rmse_m").find("a: gnss.errors.horizontal_sigma_m = 0.15"),
            std::string::npos);
}

// The campaign report says what was run: the campaign file, the seeds, the form and the hil
// that merged it (it began with the verdict alone).
TEST(CampaignReportTest, SaysWhatWasRun) {
  json s = Summary(1);
  s["campaign"] = "grade-sweep";
  s["scenario_dir"] = "vectors/campaigns/grade.yaml";
  s["seeds"] = 2;
  s["short_form"] = true;
  const std::string html = CampaignHtml(s);
  EXPECT_NE(html.find("<h2>What was run</h2>"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>campaign file</th><td>vectors/campaigns/grade.yaml</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><th>seeds per group</th><td>2</td></tr>"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>form</th><td>short"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>merged by</th><td>hil "), std::string::npos);
}

// The x axis tick labels of a CDF plot (11-pt labels centred under the axis).
std::vector<double> XTicks(const std::string& svg) {
  std::vector<double> out;
  const std::string mark = "font-size=\"11\" text-anchor=\"middle\">";
  for (std::size_t k = svg.find(mark); k != std::string::npos; k = svg.find(mark, k + 1))
    out.push_back(std::stod(svg.substr(k + mark.size())));
  return out;
}

TEST(CampaignReportTest, GroupsOfVeryDifferentScalesShareALogAxis) {
  const std::string same = CdfSvg(Summary(1), "horizontal_rmse_m");
  const std::string apart = CdfSvg(Summary(100), "horizontal_rmse_m");
  EXPECT_EQ(same.find("log scale"), std::string::npos);
  EXPECT_NE(apart.find("log scale"), std::string::npos);
  // the x ticks span both groups and step by one ratio (a geometric axis)
  const std::vector<double> ticks = XTicks(apart);
  ASSERT_EQ(ticks.size(), 5u) << apart;
  EXPECT_LT(ticks.front(), 0.1);
  EXPECT_GT(ticks.back(), 13.0);
  EXPECT_NEAR(ticks[2] / ticks[1], ticks[1] / ticks[0], 0.02 * ticks[1] / ticks[0]);
  const std::vector<double> linear = XTicks(same);
  ASSERT_GE(linear.size(), 3u);
  EXPECT_NEAR(linear[2] - linear[1], linear[1] - linear[0], 1e-3);
}

// A linear CDF axis is labelled at round values (0.0705, 0.233, 0.395 read as noise in
// receiver_grade_sweep's report), and the legend starts below the axis label, not on it.
TEST(CampaignReportTest, LinearCdfTicksAreRoundAndTheLegendClearsTheAxisLabel) {
  const std::string svg = CdfSvg(Summary(1), "horizontal_rmse_m");  // values 0.1 to 0.13
  for (const double t : XTicks(svg)) {
    const double steps = t / 0.01;  // a step of 1, 2 or 5 x 10^k: here 0.01 or 0.005
    EXPECT_NEAR(steps * 2, std::round(steps * 2), 1e-6) << t;
  }
  const std::size_t label = svg.find("font-size=\"12\" text-anchor=\"middle\">horizontal_rmse_m");
  ASSERT_NE(label, std::string::npos);
  const auto y_before = [&](std::size_t at) {
    const std::size_t y = svg.rfind(" y=\"", at);
    return std::stod(svg.substr(y + 4));
  };
  const std::size_t first_legend = svg.find(" (2 runs)</text>");
  ASSERT_NE(first_legend, std::string::npos);
  EXPECT_GE(y_before(first_legend) - y_before(label), 12.0);
}

}  // namespace
}  // namespace hil::harness

// The RTK rover's section of the report (rtk_rover_report.h): the timeline as a step chart of
// carrSoln over the run, each state held from its change to the next, the last one to the end.
#include "hil/harness/report/rtk_rover_report.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace hil::harness {
namespace {

RtkRoverReport CutTimeline() {
  RtkRoverReport r;
  // none, float 1.6 s, fixed 11.6 s, float after the cut 64.4 s
  r.timeline = {{0.0, 0, -1}, {1.6, 1, 0.6}, {11.6, 2, 0.6}, {64.4, 1, 5.2}};
  return r;
}

TEST(RtkRoverReport, TimelineChartIsAStepPerChange) {
  const PlotChart c = RtkTimelineChart(CutTimeline(), 150.0);
  ASSERT_EQ(c.series.size(), 1U);
  const PlotSeries& s = c.series[0];
  const std::vector<double> want_x{0.0, 1.6, 1.6, 11.6, 11.6, 64.4, 64.4, 150.0};
  const std::vector<double> want_y{0, 0, 1, 1, 2, 2, 1, 1};
  EXPECT_EQ(s.x, want_x);
  EXPECT_EQ(s.y, want_y);
  ASSERT_TRUE(c.range.has_value());
  EXPECT_EQ(c.range->x1, 150.0);
  EXPECT_EQ(c.id, "rtk-timeline");
  const std::string svg = RenderSvg(c);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
}

TEST(RtkRoverReport, NoChangeNoSeries) {
  const PlotChart c = RtkTimelineChart(RtkRoverReport{}, 60.0);
  EXPECT_TRUE(c.series.empty());
  EXPECT_NE(RenderSvg(c).find("no RTK state change"), std::string::npos);
}

TEST(RtkRoverReport, HeadingFiguresOnlyWithAMovingBase) {
  RtkRoverReport r = CutTimeline();
  EXPECT_FALSE(RtkRoverJson(r).contains("heading"));
  r.heading_valid_epochs = 241;
  r.heading_rms_error_deg = 0.21;
  r.heading_max_error_deg = 0.5;
  r.acc_heading_mean_deg = 0.41;
  const nlohmann::json j = RtkRoverJson(r);
  ASSERT_TRUE(j.contains("heading"));
  EXPECT_EQ(j["heading"]["valid_epochs"].get<int>(), 241);
  EXPECT_DOUBLE_EQ(j["heading"]["rms_error_deg"].get<double>(), 0.21);
  std::string html;
  AppendRtkRoverHtml(html, r);
  EXPECT_NE(html.find("Dual-antenna heading: 241 epochs"), std::string::npos) << html;
}

TEST(RtkRoverReport, FiguresAreCriterionMetrics) {
  RtkRoverReport r = CutTimeline();
  r.epochs = 150;
  r.epochs_float = 12;
  r.epochs_fixed = 53;
  r.rtcm_frames = 140;
  r.rtcm_crc_failed = 1;
  std::map<std::string, std::optional<double>> t;
  AddRtkRoverMetrics(r, t);
  EXPECT_EQ(t.at("rtk_rover.epochs"), 150.0);
  EXPECT_DOUBLE_EQ(*t.at("rtk_rover.fixed_fraction"), 53.0 / 150.0);
  EXPECT_DOUBLE_EQ(*t.at("rtk_rover.float_fraction"), 12.0 / 150.0);
  EXPECT_EQ(t.at("rtk_rover.time_to_first_float_s"), 1.6);
  EXPECT_EQ(t.at("rtk_rover.time_to_first_fixed_s"), 11.6);
  EXPECT_EQ(t.at("rtk_rover.fixed_losses"), 1.0);  // fixed → float at 64.4 s
  EXPECT_EQ(t.at("rtk_rover.rtcm_crc_failed"), 1.0);
  // no moving base: no heading figure to judge, which a criterion then reports as missing
  EXPECT_EQ(t.at("rtk_rover.heading_valid_epochs"), 0.0);
  EXPECT_FALSE(t.at("rtk_rover.heading_rms_error_deg").has_value());
  r.heading_valid_epochs = 241;
  r.heading_rms_error_deg = 0.34;
  r.heading_max_error_deg = 0.61;
  AddRtkRoverMetrics(r, t);
  EXPECT_EQ(t.at("rtk_rover.heading_rms_error_deg"), 0.34);
  EXPECT_EQ(t.at("rtk_rover.heading_max_error_deg"), 0.61);
}

TEST(RtkRoverReport, NeverFixedHasNoTimeToFix) {
  RtkRoverReport r;
  r.timeline = {{0.0, 0, -1}, {3.0, 1, 1.0}};
  std::map<std::string, std::optional<double>> t;
  AddRtkRoverMetrics(r, t);
  EXPECT_EQ(t.at("rtk_rover.time_to_first_float_s"), 3.0);
  EXPECT_FALSE(t.at("rtk_rover.time_to_first_fixed_s").has_value());
  EXPECT_FALSE(t.at("rtk_rover.fixed_fraction").has_value());  // no epochs counted
  EXPECT_EQ(t.at("rtk_rover.fixed_losses"), 0.0);
}

TEST(RtkRoverReport, NoRoverNoMetrics) {
  std::map<std::string, std::optional<double>> t;
  AddRtkRoverMetrics(std::nullopt, t);
  EXPECT_TRUE(t.empty());
}

}  // namespace
}  // namespace hil::harness

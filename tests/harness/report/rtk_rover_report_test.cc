// The RTK rover's section of the report (rtk_rover_report.h): the timeline as a step chart of
// carrSoln over the run, each state held from its change to the next, the last one to the end.
#include "hil/harness/report/rtk_rover_report.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hil::harness

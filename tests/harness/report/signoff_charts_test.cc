// The sign-off report's charts: the map fits the data (not the planned path's margin) with equal
// axes, the zoom frames the worst segment, outages are shaded where they are, the NEES chart
// carries its chi-square bands, and the cross-track chart draws the open loop's XTE.
#include "hil/harness/report/signoff_charts.h"

#include <algorithm>
#include <cmath>
#include <regex>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

// A 30 m x 3 m strip: the truth goes 30 m east in 30 s, the estimate 0.2 m north of it with one
// 1.5 m excursion at t = 6 s; raw fixes 0.4 m south; the planned path runs on 200 m beyond the
// field (the scenario's path covers the run plus margin).
class SignoffChartsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int i = 0; i <= 300; ++i) {
      const double t = 0.1 * i, e = t, n = 1.5 + std::sin(t) * 1.5;
      series_.truth_t_s.push_back(t);
      series_.truth_en_m.emplace_back(e, n);
    }
    for (int i = 0; i <= 30; ++i) {
      const double t = i, e = t, n = 1.5 + std::sin(t) * 1.5;
      ErrorSample s;
      s.t = TimeFromSeconds(t);
      s.truth_enu_m = {e, n, 0};
      s.est_enu_m = {e, n + (i == 6 ? 1.5 : 0.2), 0};
      s.err_enu_m = s.est_enu_m - s.truth_enu_m;
      s.xte_m = s.err_enu_m.y();
      s.nees_horizontal = i == 6 ? 40.0 : 1.5;
      series_.estimate_errors.push_back(s);
      ErrorSample f = s;
      f.est_enu_m = {e, n - 0.4, 0};
      f.err_enu_m = f.est_enu_m - f.truth_enu_m;
      f.xte_m = f.err_enu_m.y();
      series_.fix_errors.push_back(f);
    }
    series_.path_en_m = {{-100, 1.5}, {209, 1.5}};
    OutageMetrics o;
    o.start_s = 3;
    o.end_s = 5;
    report_.outages.push_back(o);
  }

  RunReport report_;
  ReportSeries series_;
};

TEST_F(SignoffChartsTest, MapFitsTheDataWithEqualAxesNotThePathsMargin) {
  const PlotChart map = MapChart(report_, series_);
  ASSERT_TRUE(map.equal_aspect);
  const PlotRange r = ChartRange(map);
  // every point of the truth, the estimate and the fixes is inside
  for (const auto& p : series_.truth_en_m) {
    EXPECT_GE(p.x(), r.x0);
    EXPECT_LE(p.x(), r.x1);
    EXPECT_GE(p.y(), r.y0);
    EXPECT_LE(p.y(), r.y1);
  }
  for (const auto& s : series_.fix_errors) EXPECT_GE(s.est_enu_m.y(), r.y0);
  // the data spans 30 m east: the axes show a few metres more, not the path's 309 m
  const double data_e = 30.0, data_n = 3.0 + 1.5 + 0.4;
  EXPECT_LT(r.x1 - r.x0, 1.3 * std::max(data_e, data_n * (map.width_px / 1.0) / map.height_px));
  // equal axes: metres per pixel the same on both (plot area 810 x (620 - 36 - 52 - 36))
  const double pw = map.width_px - 90.0, ph = map.height_px - 36.0 - 52 - 18.0 * 2;
  EXPECT_NEAR((r.x1 - r.x0) / pw, (r.y1 - r.y0) / ph, 1e-9);
  // the planned path is drawn, clipped
  EXPECT_FALSE(map.series.front().fits);
  EXPECT_EQ(map.series.front().x.size(), 2U);
}

// The issue's field: 9 m wide, 60 m long, driven up at east 0 and back down at east 9. A fixed
// 900 x 620 frame showed it at about 100 m east to west; the map's frame takes the field's shape.
TEST(SignoffMapTest, LongNarrowFieldIsDrawnTallNotInAWideFrame) {
  ReportSeries s;
  for (int i = 0; i <= 120; ++i) {
    const double t = i, e = i <= 60 ? 0.0 : 9.0, n = i <= 60 ? i : 120.0 - i;
    s.truth_t_s.push_back(t);
    s.truth_en_m.emplace_back(e, n);
    ErrorSample x;
    x.t = TimeFromSeconds(t);
    x.truth_enu_m = {e, n, 0};
    x.est_enu_m = {e + 0.1, n, 0};
    x.err_enu_m = x.est_enu_m - x.truth_enu_m;
    s.estimate_errors.push_back(x);
    s.fix_errors.push_back(x);
  }
  const PlotChart map = MapChart(RunReport{}, s);
  const PlotRange r = ChartRange(map);
  EXPECT_GT(map.height_px, map.width_px);
  EXPECT_LT(r.x1 - r.x0, 30.0);         // the field's 9.1 m across, not 100 m
  EXPECT_LT(r.y1 - r.y0, 1.15 * 60.0);  // and its 60 m along, padded
  EXPECT_GE(r.x0, -12.0);
  // equal axes still: metres per pixel the same on both
  const double pw = map.width_px - 90.0;
  const int rows = (4 + map.legend_columns - 1) / map.legend_columns;
  const double ph = map.height_px - 36.0 - 52 - 18.0 * rows;
  EXPECT_NEAR((r.x1 - r.x0) / pw, (r.y1 - r.y0) / ph, 1e-9);
  // the zoom's box (0.2 m on a 60 m map) is drawn as a visible marker, its label on a halo
  const std::string svg = RenderSvg(map);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      svg, m, std::regex(R"re(<rect class="box" x="[-0-9.]+" y="[-0-9.]+" width="([0-9.]+)")re")));
  EXPECT_GE(std::stod(m[1]), 14.0);
  EXPECT_NE(svg.find("class=\"box-label\""), std::string::npos);
  EXPECT_NE(svg.find("paint-order=\"stroke\""), std::string::npos);
}

TEST_F(SignoffChartsTest, ZoomFramesTheWorstSegmentAndTheMapMarksIt) {
  const auto w = FindWorstSegment(series_);
  ASSERT_TRUE(w);
  EXPECT_DOUBLE_EQ(w->t_worst_s, 6.0);
  EXPECT_NEAR(w->error_m, 1.5, 1e-12);
  const auto zoom = WorstSegmentChart(series_);
  ASSERT_TRUE(zoom);
  const PlotRange z = ChartRange(*zoom);
  // the worst estimate and its truth are inside the zoom, which is smaller than the map
  const ErrorSample& worst = series_.estimate_errors[6];
  EXPECT_GT(worst.est_enu_m.y(), z.y0);
  EXPECT_LT(worst.est_enu_m.y(), z.y1);
  EXPECT_GT(worst.est_enu_m.x(), z.x0);
  EXPECT_LT(worst.est_enu_m.x(), z.x1);
  const PlotRange m = ChartRange(MapChart(report_, series_));
  EXPECT_LT((z.x1 - z.x0) * (z.y1 - z.y0), (m.x1 - m.x0) * (m.y1 - m.y0));
  // a square of half side 2 x 1.5 m around the midpoint of the truth and the estimate at 6 s
  EXPECT_NEAR(w->range.x1 - w->range.x0, 6.0, 1e-12);
  EXPECT_NEAR((w->range.y0 + w->range.y1) / 2, worst.truth_enu_m.y() + 0.75, 1e-12);
  // the estimates at 0 s and at 20 s are outside it
  EXPECT_GT(w->range.x0, series_.estimate_errors[0].est_enu_m.x());
  EXPECT_LT(w->range.x1, series_.estimate_errors[20].est_enu_m.x());
  ASSERT_EQ(MapChart(report_, series_).boxes.size(), 1U);
}

TEST_F(SignoffChartsTest, OutagesAreShadedWhereTheyAre) {
  const PlotChart c = ErrorTimeChart(report_, series_);
  ASSERT_EQ(c.bands.size(), 1U);
  EXPECT_DOUBLE_EQ(c.bands[0].x0, 3.0);
  EXPECT_DOUBLE_EQ(c.bands[0].x1, 5.0);
  // the shaded rectangle's pixels are the outage's times on the chart's x axis
  const std::string svg = RenderSvg(c);
  std::smatch m;
  const std::regex band(R"re(<rect class="xband" x="([0-9.]+)" y="[0-9.]+" width="([0-9.]+)")re");
  ASSERT_TRUE(std::regex_search(svg, m, band));
  ASSERT_EQ(m.size(), 3U) << svg.substr(0, 600);
  const PlotRange r = ChartRange(c);
  const double pw = c.width_px - 90.0;
  const auto px = [&](double t) { return 70 + (t - r.x0) / (r.x1 - r.x0) * pw; };
  EXPECT_NEAR(std::stod(m[1]), px(3.0), 0.01);
  EXPECT_NEAR(std::stod(m[2]), px(5.0) - px(3.0), 0.02);
  // nothing shaded when the run had no outage
  report_.outages.clear();
  EXPECT_EQ(RenderSvg(ErrorTimeChart(report_, series_)).find("class=\"xband\""), std::string::npos);
}

TEST_F(SignoffChartsTest, NeesChartHasItsChiSquareBandsOnALogAxis) {
  const PlotChart c = NeesChart(series_);
  EXPECT_TRUE(c.y_log);
  ASSERT_EQ(c.y_bands.size(), 2U);
  EXPECT_DOUBLE_EQ(c.y_bands[1].x1, 4.0);  // the default criterion nees_horizontal's bound
  ASSERT_FALSE(c.series.empty());
  EXPECT_EQ(c.series[0].y.size(), 31U);
  EXPECT_DOUBLE_EQ(*std::max_element(c.series[0].y.begin(), c.series[0].y.end()), 40.0);
  const PlotRange r = ChartRange(c);  // log10: 40 and the band's 0.01 are inside
  EXPECT_GT(r.y1, std::log10(40.0));
  EXPECT_LT(r.y0, std::log10(kNeesSampleLow));
  // an estimator without a sigma: an empty chart that says why
  for (auto& e : series_.estimate_errors) e.nees_horizontal.reset();
  const PlotChart none = NeesChart(series_);
  EXPECT_TRUE(none.series.empty());
  EXPECT_NE(RenderSvg(none).find("reports no position sigma"), std::string::npos);
}

TEST_F(SignoffChartsTest, OpenLoopCrossTrackAgainstDistanceTravelled) {
  const PlotChart c = CrossTrackChart(report_, series_);
  ASSERT_EQ(c.series.size(), 2U);  // estimate and raw fixes (no tracking: open loop)
  ASSERT_EQ(c.series[0].x.size(), 31U);
  // distance travelled along the truth at t = 0..30 s: monotonic, ends at the track's length
  double length = 0;
  for (std::size_t i = 1; i < series_.truth_en_m.size(); ++i)
    length += (series_.truth_en_m[i] - series_.truth_en_m[i - 1]).norm();
  EXPECT_DOUBLE_EQ(c.series[0].x.front(), 0.0);
  EXPECT_NEAR(c.series[0].x.back(), length, 1e-9);
  EXPECT_TRUE(std::is_sorted(c.series[0].x.begin(), c.series[0].x.end()));
  EXPECT_DOUBLE_EQ(c.series[0].y[6], 1.5);
  EXPECT_DOUBLE_EQ(c.series[1].y[0], -0.4);
}

}  // namespace
}  // namespace hil::harness

// Closed loop's plots: each SVG's polylines are the run's data, mapped by one affine map per axis.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/harness/report/report.h"
#include "hil/harness/report/report_html.h"

namespace hil::harness {
namespace {

struct Polyline {
  std::string color;
  std::vector<std::pair<double, double>> px;
};

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<Polyline> Polylines(const std::string& svg) {
  std::vector<Polyline> out;
  const std::regex re(R"re(<polyline fill="none" stroke="([^"]+)"[^>]*points="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator();
       ++it) {
    Polyline p;
    p.color = (*it)[1];
    std::istringstream pts((*it)[2].str());
    double x = 0, y = 0;
    char comma = 0;
    while (pts >> x >> comma >> y) p.px.emplace_back(x, y);
    out.push_back(p);
  }
  return out;
}

// The pixels of `p` are a·data + b on each axis (one map for x, one for y, as a chart draws):
// fitted on the points of the smallest and the largest value, checked on every point (the SVG
// rounds to 0.01 px). x grows right, y grows up.
void ExpectAffineImage(const Polyline& p, const std::vector<double>& x,
                       const std::vector<double>& y) {
  ASSERT_EQ(p.px.size(), x.size());
  ASSERT_GE(x.size(), 2U);
  const auto span = [](const std::vector<double>& v) {
    return std::pair<std::size_t, std::size_t>(std::min_element(v.begin(), v.end()) - v.begin(),
                                               std::max_element(v.begin(), v.end()) - v.begin());
  };
  const auto [xlo, xhi] = span(x);
  const auto [ylo, yhi] = span(y);
  const double ax = (p.px[xhi].first - p.px[xlo].first) / (x[xhi] - x[xlo]);
  const double ay = (p.px[yhi].second - p.px[ylo].second) / (y[yhi] - y[ylo]);
  EXPECT_GT(ax, 0);
  EXPECT_LT(ay, 0);  // SVG's y runs down
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(p.px[i].first, p.px[xlo].first + ax * (x[i] - x[xlo]), 0.02) << i;
    EXPECT_NEAR(p.px[i].second, p.px[ylo].second + ay * (y[i] - y[ylo]), 0.02) << i;
  }
}

class ClosedLoopPlotsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cl_plots_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir_ / "plots");
    report_.tracking = TrackingMetrics{};
    for (int i = 0; i <= 20; ++i) {
      const double e = 0.5 * i, n = 0.3 * std::sin(0.4 * i);
      series_.truth_en_m.emplace_back(e, n);
      ErrorSample s;
      s.est_enu_m = {e + 0.01, n - 0.02 * i, 0};
      series_.estimate_errors.push_back(s);
      report_.tracking->s_m.push_back(e);
      report_.tracking->xte_m.push_back(n);
      series_.tick_t_s.push_back(0.1 * i);
      series_.commanded_yaw_rate_dps.push_back(10 * std::cos(0.3 * i));
      series_.actual_yaw_rate_dps.push_back(9 * std::cos(0.3 * i - 0.2) + 0.5);
    }
    series_.path_en_m = {{0, 0}, {6, 0}, {10, 1}};
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  RunReport report_;
  ReportSeries series_;
};

TEST_F(ClosedLoopPlotsTest, PolylinesAreTheRunsData) {
  std::vector<std::string> files;
  WriteClosedLoopPlots(report_, series_, dir_.string(), files);
  ASSERT_EQ(files, (std::vector<std::string>{"plots/closed_loop_path.svg", "plots/cross_track.svg",
                                             "plots/steering.svg"}));

  const std::vector<Polyline> path = Polylines(ReadAll(dir_ / files[0]));
  ASSERT_EQ(path.size(), 3U);  // planned path, truth, estimate
  std::vector<double> pe, pn, te, tn, ee, en;
  for (const auto& v : series_.path_en_m) pe.push_back(v.x()), pn.push_back(v.y());
  for (const auto& v : series_.truth_en_m) te.push_back(v.x()), tn.push_back(v.y());
  for (const auto& s : series_.estimate_errors)
    ee.push_back(s.est_enu_m.x()), en.push_back(s.est_enu_m.y());
  ExpectAffineImage(path[0], pe, pn);
  ExpectAffineImage(path[1], te, tn);
  ExpectAffineImage(path[2], ee, en);
  // one map for all three series and equal metres per pixel on both axes (a map, not a graph)
  const double scale_x = (path[1].px.back().first - path[1].px[0].first) / (te.back() - te[0]);
  const double path_scale_x = (path[0].px.back().first - path[0].px[0].first) / (pe.back() - pe[0]);
  EXPECT_NEAR(scale_x, path_scale_x, 1e-3 * scale_x);
  const double scale_y = (path[0].px.back().second - path[0].px[0].second) / (pn.back() - pn[0]);
  EXPECT_NEAR(scale_x, -scale_y, 1e-3 * scale_x);

  const std::vector<Polyline> xte = Polylines(ReadAll(dir_ / files[1]));
  ASSERT_EQ(xte.size(), 1U);
  ExpectAffineImage(xte[0], report_.tracking->s_m, report_.tracking->xte_m);

  const std::string steering = ReadAll(dir_ / files[2]);
  const std::vector<Polyline> yaw = Polylines(steering);
  ASSERT_EQ(yaw.size(), 2U);  // commanded, actual
  ExpectAffineImage(yaw[0], series_.tick_t_s, series_.commanded_yaw_rate_dps);
  ExpectAffineImage(yaw[1], series_.tick_t_s, series_.actual_yaw_rate_dps);
  EXPECT_NE(yaw[0].color, yaw[1].color);
  EXPECT_NE(steering.find("commanded"), std::string::npos);
  EXPECT_NE(steering.find("actual"), std::string::npos);
}

// A tractor on ISO 11783-7 has no yaw-rate ticks but its steering ECU's road-wheel angles: those
// are its steering chart (it was an empty "no data" frame); a run with neither has no chart.
TEST_F(ClosedLoopPlotsTest, SteeringEcuRunDrawsRoadWheelAnglesAndNoTicksDrawNoChart) {
  series_.commanded_steer_deg.clear();
  for (std::size_t i = 0; i < series_.tick_t_s.size(); ++i) {
    series_.commanded_steer_deg.push_back(20 * std::sin(0.2 * static_cast<double>(i)));
    series_.actual_steer_deg.push_back(18 * std::sin(0.2 * static_cast<double>(i) - 0.3));
  }
  series_.commanded_yaw_rate_dps.clear();
  series_.actual_yaw_rate_dps.clear();
  std::vector<std::string> files;
  WriteClosedLoopPlots(report_, series_, dir_.string(), files);
  ASSERT_EQ(files.size(), 3U);
  const std::string steering = ReadAll(dir_ / files[2]);
  const std::vector<Polyline> angle = Polylines(steering);
  ASSERT_EQ(angle.size(), 2U);
  ExpectAffineImage(angle[0], series_.tick_t_s, series_.commanded_steer_deg);
  ExpectAffineImage(angle[1], series_.tick_t_s, series_.actual_steer_deg);
  EXPECT_NE(steering.find("road-wheel angle"), std::string::npos);
  EXPECT_EQ(steering.find("no data"), std::string::npos);

  series_.tick_t_s.clear();
  series_.commanded_steer_deg.clear();
  series_.actual_steer_deg.clear();
  EXPECT_FALSE(SteeringChart(series_));
  std::filesystem::remove(dir_ / "plots/steering.svg");
  files.clear();
  WriteClosedLoopPlots(report_, series_, dir_.string(), files);
  EXPECT_EQ(files,
            (std::vector<std::string>{"plots/closed_loop_path.svg", "plots/cross_track.svg"}));
}

}  // namespace
}  // namespace hil::harness

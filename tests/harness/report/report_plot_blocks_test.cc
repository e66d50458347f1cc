// The plot pieces of report.html: series through east/north points, and one chart written into the
// run directory and listed.
#include "hil/harness/report/report_plot_blocks.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

TEST(ReportPlotBlocksTest, EnSeriesTakesEastAsXAndNorthAsY) {
  const PlotSeries s = EnSeries("truth", kTruthColor, {{1, 2}, {3, -4}});
  EXPECT_EQ(s.label, "truth");
  EXPECT_EQ(s.color, kTruthColor);
  EXPECT_EQ(s.style, PlotSeries::Style::kLine);
  EXPECT_EQ(s.x, (std::vector<double>{1, 3}));
  EXPECT_EQ(s.y, (std::vector<double>{2, -4}));
}

TEST(ReportPlotBlocksTest, EstimatedEnSeriesTakesTheEstimateNotTheTruth) {
  ErrorSample e;
  e.est_enu_m = {5, 6, 7};
  e.truth_enu_m = {50, 60, 70};
  const PlotSeries s = EstimatedEnSeries("fixes", kGnssColor, {e, e}, PlotSeries::Style::kPoints);
  EXPECT_EQ(s.style, PlotSeries::Style::kPoints);
  EXPECT_EQ(s.x, (std::vector<double>{5, 5}));
  EXPECT_EQ(s.y, (std::vector<double>{6, 6}));
  EXPECT_TRUE(s.bar_width == 0);
}

TEST(ReportPlotBlocksTest, WritePlotWritesTheRenderedChartAndListsItsRelativePath) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("report_plot_blocks_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "plots");
  PlotChart c;
  c.title = "t";
  c.series = {EnSeries("truth", kTruthColor, {{0, 0}, {1, 1}})};
  std::vector<std::string> files{"earlier.svg"};
  WritePlot(c, dir.string(), "plots/x.svg", files);
  EXPECT_EQ(files, (std::vector<std::string>{"earlier.svg", "plots/x.svg"}));
  std::ifstream in(dir / "plots/x.svg");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), RenderSvg(c));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

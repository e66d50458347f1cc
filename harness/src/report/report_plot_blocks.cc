#include "hil/harness/report/report_plot_blocks.h"

#include "hil/harness/report/output_file.h"

namespace hil::harness {

PlotSeries NamedSeries(const std::string& label, const char* color, PlotSeries::Style style) {
  return {label, color, style, {}, {}, 0};
}

PlotSeries EnSeries(const std::string& label, const char* color,
                    const std::vector<Eigen::Vector2d>& en_m, PlotSeries::Style style) {
  PlotSeries s = NamedSeries(label, color, style);
  for (const auto& p : en_m) s.x.push_back(p.x()), s.y.push_back(p.y());
  return s;
}

PlotSeries EstimatedEnSeries(const std::string& label, const char* color,
                             const std::vector<ErrorSample>& errors, PlotSeries::Style style) {
  PlotSeries s = NamedSeries(label, color, style);
  for (const auto& e : errors) s.x.push_back(e.est_enu_m.x()), s.y.push_back(e.est_enu_m.y());
  return s;
}

void WritePlot(const PlotChart& chart, const std::string& dir, const std::string& file,
               std::vector<std::string>& files) {
  WriteOutputFile(dir + "/" + file, RenderSvg(chart));
  files.push_back(file);
}

}  // namespace hil::harness

#include "hil/harness/characterize/characterize_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "hil/harness/report/svg_plot.h"

namespace hil::harness {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kRtHourPerRtS = 60.0;  // √(3600 s)
constexpr double kRadpsToDegph = kRadToDeg * 3600.0;
constexpr const char* kAxes[] = {"x", "y", "z"};
constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c"};

nlohmann::json Xyz(const AxisLists& v) { return {{"x", v[0]}, {"y", v[1]}, {"z", v[2]}}; }
nlohmann::json Xyz(const Eigen::Vector3d& v) { return {{"x", v.x()}, {"y", v.y()}, {"z", v.z()}}; }
template <typename F>
nlohmann::json PerAxis(const std::array<NoiseTerms, 3>& t, F f) {
  nlohmann::json o;
  for (int a = 0; a < 3; ++a) o[kAxes[a]] = f(t[static_cast<std::size_t>(a)]);
  return o;
}
nlohmann::json Optional(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json FitDetails(const std::array<NoiseTerms, 3>& t) {
  return PerAxis(t, [](const NoiseTerms& n) {
    return nlohmann::json{
        {"white_tau_s", n.white_tau_s},
        {"white_local_slope", n.white_slope},
        {"bias_instability_tau_s", n.bias_instability_tau_s},
        {"bias_instability_resolved", n.bias_instability_resolved},
        {"rate_random_walk_tau_s",
         n.rate_random_walk ? nlohmann::json(n.rate_random_walk_tau_s) : nlohmann::json(nullptr)}};
  });
}

void WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error(path + ": cannot write");
}

std::vector<double> Log10(const std::vector<double>& v, double scale = 1) {
  std::vector<double> o;
  for (double x : v) o.push_back(x > 0 ? std::log10(x * scale) : std::nan(""));
  return o;
}

// a straight reference line on log axes: y = level·τ^slope over the τ range
PlotSeries Reference(const std::string& label, const std::vector<double>& x, double level,
                     double slope) {
  PlotSeries s{label, "#7f7f7f", PlotSeries::Style::kLine, {}, {}, 0};
  for (double t : {x.front(), x.back()}) {
    s.x.push_back(std::log10(t));
    s.y.push_back(std::log10(level * std::pow(t, slope)));
  }
  return s;
}

PlotChart AllanChart(const Characterization& c, const AxisLists& adev, double scale,
                     const std::string& what, const std::string& unit) {
  PlotChart ch;
  ch.title = what + " overlapping Allan deviation (" + std::to_string(c.samples) + " samples, " +
             std::to_string(c.step_s * 1e3).substr(0, 5) + " ms)";
  ch.x_label = "log10(tau / s)";
  ch.y_label = "log10(sigma / " + unit + ")";
  for (std::size_t a = 0; a < 3; ++a)
    ch.series.push_back({std::string(kAxes[a]), kColors[a], PlotSeries::Style::kLine,
                         Log10(c.tau_s), Log10(adev[a], scale), 0});
  return ch;
}

PlotChart PsdChart(const Characterization& c, const AxisLists& psd, const std::string& what,
                   const std::string& unit) {
  PlotChart ch;
  ch.title = what + " PSD, Welch (" + std::to_string(c.psd_segments) + " Hann segments of " +
             std::to_string(c.psd_segment) + ")";
  ch.x_label = "log10(f / Hz)";
  ch.y_label = "log10(PSD / (" + unit + "))";
  const std::vector<double> f(c.psd_freq_hz.begin() + 1, c.psd_freq_hz.end());  // no DC
  for (std::size_t a = 0; a < 3; ++a)
    ch.series.push_back({std::string(kAxes[a]), kColors[a], PlotSeries::Style::kLine, Log10(f),
                         Log10(std::vector<double>(psd[a].begin() + 1, psd[a].end())), 0});
  return ch;
}

}  // namespace

nlohmann::json CharacterizationJson(const Characterization& c, const std::string& source,
                                    const CharacterizeReferences& ref) {
  nlohmann::json j;
  j["source"] = source;
  j["format"] = c.format;
  j["notes"] = c.notes;
  j["log_start_s"] = c.log_start_s;
  j["log_length_s"] = c.log_length_s;
  j["step_s"] = c.step_s;
  j["max_gap_s"] = c.max_gap_s;
  j["window"] = {{"from_s", c.from_s}, {"to_s", c.to_s}, {"samples", c.samples}};
  nlohmann::json still = nlohmann::json::array();
  for (const StillPeriod& p : c.still_periods)
    still.push_back({{"from_s", p.from_s}, {"to_s", p.to_s}});
  j["still_periods"] = still;
  j["mean_gyro_radps"] = Xyz(c.mean_gyro_radps);
  j["mean_accel_mps2"] = Xyz(c.mean_accel_mps2);
  j["tau_s"] = c.tau_s;
  j["allan_gyro_radps"] = Xyz(c.adev_gyro_radps);
  j["allan_accel_mps2"] = Xyz(c.adev_accel_mps2);
  j["arw_deg_per_rthr"] = PerAxis(
      c.gyro_terms, [](const NoiseTerms& n) { return n.white * kRadToDeg * kRtHourPerRtS; });
  j["vrw_mps_per_rthr"] =
      PerAxis(c.accel_terms, [](const NoiseTerms& n) { return n.white * kRtHourPerRtS; });
  j["gyro_bias_instability_degph"] =
      PerAxis(c.gyro_terms, [](const NoiseTerms& n) { return n.bias_instability * kRadpsToDegph; });
  j["accel_bias_instability_mps2"] =
      PerAxis(c.accel_terms, [](const NoiseTerms& n) { return n.bias_instability; });
  j["gyro_rate_random_walk_degph_per_rthr"] = PerAxis(c.gyro_terms, [](const NoiseTerms& n) {
    return n.rate_random_walk ? nlohmann::json(*n.rate_random_walk * kRadpsToDegph * kRtHourPerRtS)
                              : nlohmann::json(nullptr);
  });
  j["accel_rate_random_walk_mps2_per_rthr"] = PerAxis(c.accel_terms, [](const NoiseTerms& n) {
    return n.rate_random_walk ? nlohmann::json(*n.rate_random_walk * kRtHourPerRtS)
                              : nlohmann::json(nullptr);
  });
  j["fit"] = {{"gyro", FitDetails(c.gyro_terms)}, {"accel", FitDetails(c.accel_terms)}};
  j["psd"] = {{"method", "Welch, periodic Hann window, 50 % overlap, mean removed, one-sided"},
              {"segment", c.psd_segment},
              {"segments", c.psd_segments},
              {"freq_hz", c.psd_freq_hz},
              {"gyro_rad2ps2_per_hz", Xyz(c.psd_gyro_rad2ps2_per_hz)},
              {"accel_m2ps4_per_hz", Xyz(c.psd_accel_m2ps4_per_hz)},
              {"white_band_hz", {c.psd_band_lo_hz, c.psd_band_hi_hz}}};
  j["psd_arw_deg_per_rthr"] = Xyz(Eigen::Vector3d(c.psd_white_gyro * kRadToDeg * kRtHourPerRtS));
  j["psd_vrw_mps_per_rthr"] = Xyz(Eigen::Vector3d(c.psd_white_accel * kRtHourPerRtS));
  j["references"] = {{"label", ref.label},
                     {"arw_deg_per_rthr", Optional(ref.arw_deg_per_rthr)},
                     {"vrw_mps_per_rthr", Optional(ref.vrw_mps_per_rthr)},
                     {"gyro_bias_instability_degph", Optional(ref.gyro_bias_instability_degph)},
                     {"accel_bias_instability_mps2", Optional(ref.accel_bias_instability_mps2)}};
  return j;
}

void WriteCharacterizationSvgs(const Characterization& c, const CharacterizeReferences& ref,
                               const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create: " + ec.message());
  PlotChart g = AllanChart(c, c.adev_gyro_radps, kRadpsToDegph, "Gyro", "deg/h");
  if (ref.arw_deg_per_rthr)  // σ(τ) = N/√τ, N in °/√h → °/h·√s: × 60
    g.series.push_back(Reference(
        ref.label + " ARW " + std::to_string(*ref.arw_deg_per_rthr).substr(0, 6) + " deg/rt-h",
        c.tau_s, *ref.arw_deg_per_rthr * kRtHourPerRtS, -0.5));
  if (ref.gyro_bias_instability_degph)
    g.series.push_back(Reference(ref.label + " bias instability floor (0.664 B)", c.tau_s,
                                 *ref.gyro_bias_instability_degph * kBiasInstabilityFloor, 0));
  PlotChart a = AllanChart(c, c.adev_accel_mps2, 1.0, "Accelerometer", "m/s^2");
  if (ref.vrw_mps_per_rthr)
    a.series.push_back(Reference(
        ref.label + " VRW " + std::to_string(*ref.vrw_mps_per_rthr).substr(0, 6) + " m/s/rt-h",
        c.tau_s, *ref.vrw_mps_per_rthr / kRtHourPerRtS, -0.5));
  if (ref.accel_bias_instability_mps2)
    a.series.push_back(Reference(ref.label + " bias instability floor (0.664 B)", c.tau_s,
                                 *ref.accel_bias_instability_mps2 * kBiasInstabilityFloor, 0));
  WriteFile(dir + "/allan_gyro.svg", RenderSvg(g));
  WriteFile(dir + "/allan_accel.svg", RenderSvg(a));
  PlotChart pg = PsdChart(c, c.psd_gyro_rad2ps2_per_hz, "Gyro", "rad^2/s^2/Hz");
  PlotChart pa = PsdChart(c, c.psd_accel_m2ps4_per_hz, "Accelerometer", "m^2/s^4/Hz");
  const std::vector<double> f{c.psd_freq_hz[1], c.psd_freq_hz.back()};
  if (ref.arw_deg_per_rthr) {  // one-sided white level 2N², N in rad/√s
    const double n = *ref.arw_deg_per_rthr / kRadToDeg / kRtHourPerRtS;
    pg.series.push_back(Reference(ref.label + " ARW (2 N^2)", f, 2 * n * n, 0));
  }
  if (ref.vrw_mps_per_rthr) {
    const double n = *ref.vrw_mps_per_rthr / kRtHourPerRtS;
    pa.series.push_back(Reference(ref.label + " VRW (2 N^2)", f, 2 * n * n, 0));
  }
  WriteFile(dir + "/psd_gyro.svg", RenderSvg(pg));
  WriteFile(dir + "/psd_accel.svg", RenderSvg(pa));
}

void WriteAnalysedSamplesCsv(const Characterization& c, const std::string& path) {
  std::ofstream out(path);
  out << "t_s,gx_radps,gy_radps,gz_radps,ax_mps2,ay_mps2,az_mps2\n";
  char b[256];
  for (std::size_t i = 0; i < c.window.size(); ++i) {
    const Eigen::Vector3d& g = c.window.gyro_radps[i];
    const Eigen::Vector3d& a = c.window.accel_mps2[i];
    std::snprintf(b, sizeof b, "%.6f,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  c.window.t0_s + static_cast<double>(i) * c.window.step_s, g.x(), g.y(), g.z(),
                  a.x(), a.y(), a.z());
    out << b;
  }
  if (!out) throw std::runtime_error(path + ": cannot write");
}

std::string CharacterizationSummary(const Characterization& c) {
  std::string out;
  char b[400];
  std::snprintf(
      b, sizeof b,
      "%s log, %.1f s; analysed %.2f..%.2f s (%zu samples of %.2f ms), tau %.3g..%.3g s\n",
      c.format.c_str(), c.log_length_s, c.from_s, c.to_s, c.samples, c.step_s * 1e3,
      c.tau_s.front(), c.tau_s.back());
  out += b;
  for (std::size_t a = 0; a < 3; ++a) {
    const NoiseTerms& g = c.gyro_terms[a];
    const NoiseTerms& f = c.accel_terms[a];
    std::snprintf(b, sizeof b,
                  "%s: ARW %.3g deg/rt-h, gyro bias instability %s%.3g deg/h; VRW %.3g m/s/rt-h, "
                  "accel bias instability %s%.3g m/s^2\n",
                  kAxes[a], g.white * kRadToDeg * kRtHourPerRtS,
                  g.bias_instability_resolved ? "" : "<= ", g.bias_instability * kRadpsToDegph,
                  f.white * kRtHourPerRtS,
                  f.bias_instability_resolved ? "" : "<= ", f.bias_instability);
    out += b;
  }
  return out;
}

}  // namespace hil::harness

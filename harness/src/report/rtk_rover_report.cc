#include "hil/harness/report/rtk_rover_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/rtk/zed_f9p_device.h"

namespace hil::harness {
namespace {

const char* StateName(int carr_soln) {
  return carr_soln == 2 ? "fixed" : carr_soln == 1 ? "float" : "none (3-D)";
}

}  // namespace

RtkRoverReport MakeRtkRoverReport(const rtk::ZedF9pDevice& rover) {
  RtkRoverReport r;
  for (const rtk::RtkTransition& c : rover.timeline()) {
    r.timeline.push_back(
        {ToSeconds(c.t - Time{}), static_cast<int>(c.carr_soln), c.correction_age_s});
  }
  const rtk::ZedF9pStatistics& s = rover.rover_statistics();
  r.epochs = s.epochs;
  r.epochs_float = s.epochs_float;
  r.epochs_fixed = s.epochs_fixed;
  r.rtcm_frames = s.rtcm_frames;
  r.rtcm_crc_failed = s.rtcm_crc_failed;
  r.heading_valid_epochs = s.heading_valid_epochs;
  if (s.heading_valid_epochs > 0) {
    const auto n = static_cast<double>(s.heading_valid_epochs);
    r.heading_rms_error_deg = std::sqrt(s.heading_error_sum_sq_deg2 / n);
    r.heading_max_error_deg = s.heading_error_max_deg;
    r.acc_heading_mean_deg = s.acc_heading_sum_deg / n;
  }
  return r;
}

void AddRtkRoverMetrics(const std::optional<RtkRoverReport>& r,
                        std::map<std::string, std::optional<double>>& table) {
  if (!r) return;
  const auto n = static_cast<double>(r->epochs);
  const auto share = [n](std::uint64_t k) {
    return n > 0 ? std::optional<double>(static_cast<double>(k) / n) : std::nullopt;
  };
  std::optional<double> first_float, first_fixed;
  int fixed_losses = 0, previous = 0;
  for (const RtkRoverChange& c : r->timeline) {
    if (c.carr_soln >= 1 && !first_float) first_float = c.t_s;
    if (c.carr_soln == 2 && !first_fixed) first_fixed = c.t_s;
    if (previous == 2 && c.carr_soln < 2) ++fixed_losses;
    previous = c.carr_soln;
  }
  table["rtk_rover.epochs"] = n;
  table["rtk_rover.fixed_fraction"] = share(r->epochs_fixed);
  table["rtk_rover.float_fraction"] = share(r->epochs_float);
  table["rtk_rover.time_to_first_float_s"] = first_float;
  table["rtk_rover.time_to_first_fixed_s"] = first_fixed;
  table["rtk_rover.fixed_losses"] = fixed_losses;
  table["rtk_rover.rtcm_frames"] = static_cast<double>(r->rtcm_frames);
  table["rtk_rover.rtcm_crc_failed"] = static_cast<double>(r->rtcm_crc_failed);
  table["rtk_rover.heading_valid_epochs"] = static_cast<double>(r->heading_valid_epochs);
  const bool heading = r->heading_valid_epochs > 0;
  const auto h = [heading](double v) { return heading ? std::optional<double>(v) : std::nullopt; };
  table["rtk_rover.heading_rms_error_deg"] = h(r->heading_rms_error_deg);
  table["rtk_rover.heading_max_error_deg"] = h(r->heading_max_error_deg);
  table["rtk_rover.acc_heading_mean_deg"] = h(r->acc_heading_mean_deg);
}

nlohmann::json RtkRoverJson(const RtkRoverReport& r) {
  nlohmann::json timeline = nlohmann::json::array();
  for (const RtkRoverChange& c : r.timeline) {
    nlohmann::json e = {{"t_s", c.t_s}, {"carr_soln", c.carr_soln}};
    e["correction_age_s"] = c.correction_age_s >= 0 ? nlohmann::json(c.correction_age_s) : nullptr;
    timeline.push_back(e);
  }
  nlohmann::json j = {{"timeline", timeline},           {"epochs", r.epochs},
                      {"epochs_float", r.epochs_float}, {"epochs_fixed", r.epochs_fixed},
                      {"rtcm_frames", r.rtcm_frames},   {"rtcm_crc_failed", r.rtcm_crc_failed}};
  if (r.heading_valid_epochs > 0) {
    j["heading"] = {{"valid_epochs", r.heading_valid_epochs},
                    {"rms_error_deg", r.heading_rms_error_deg},
                    {"max_error_deg", r.heading_max_error_deg},
                    {"acc_heading_mean_deg", r.acc_heading_mean_deg}};
  }
  return j;
}

PlotChart RtkTimelineChart(const RtkRoverReport& r, double end_s) {
  PlotChart c;
  c.title = "RTK state of the rover (carrSoln)";
  c.x_label = "t (s)";
  c.y_label = "carrSoln: 0 none, 1 float, 2 fixed";
  c.id = "rtk-timeline";
  c.height_px = 240;
  c.empty_note = "no RTK state change";
  PlotSeries steps;
  steps.label = "carrSoln";
  for (const RtkRoverChange& k : r.timeline) {
    if (!steps.y.empty()) {
      steps.x.push_back(k.t_s);  // the previous state up to this change
      steps.y.push_back(steps.y.back());
    }
    steps.x.push_back(k.t_s);
    steps.y.push_back(k.carr_soln);
  }
  if (!steps.y.empty()) {
    steps.x.push_back(std::max(end_s, steps.x.back()));
    steps.y.push_back(steps.y.back());
    c.series.push_back(std::move(steps));
    c.range = PlotRange{0, std::max(end_s, 1.0), -0.2, 2.2};  // a chart with no state: empty
  }
  return c;
}

void AppendRtkRoverHtml(std::string& h, const RtkRoverReport& r) {
  char buf[256];
  h += "<h2>RTK rover state</h2>\n";
  std::snprintf(buf, sizeof buf,
                "<p>%llu epochs: %llu fixed, %llu float; %llu RTCM frames received, %llu with a "
                "failed CRC.</p>\n",
                static_cast<unsigned long long>(r.epochs),
                static_cast<unsigned long long>(r.epochs_fixed),
                static_cast<unsigned long long>(r.epochs_float),
                static_cast<unsigned long long>(r.rtcm_frames),
                static_cast<unsigned long long>(r.rtcm_crc_failed));
  h += buf;
  if (r.heading_valid_epochs > 0) {
    std::snprintf(buf, sizeof buf,
                  "<p>Dual-antenna heading: %llu epochs with relPosHeadingValid; error against the "
                  "truth RMS %.3f&deg;, max %.3f&deg;; mean accHeading %.3f&deg;.</p>\n",
                  static_cast<unsigned long long>(r.heading_valid_epochs), r.heading_rms_error_deg,
                  r.heading_max_error_deg, r.acc_heading_mean_deg);
    h += buf;
  }
  h += "<table><tr><th>from t (s)</th><th>carrSoln</th><th>age of corrections (s)</th></tr>\n";
  for (const RtkRoverChange& c : r.timeline) {
    if (c.correction_age_s >= 0)
      std::snprintf(buf, sizeof buf, "<tr><td>%.1f</td><td>%d %s</td><td>%.1f</td></tr>\n", c.t_s,
                    c.carr_soln, StateName(c.carr_soln), c.correction_age_s);
    else
      std::snprintf(buf, sizeof buf, "<tr><td>%.1f</td><td>%d %s</td><td>–</td></tr>\n", c.t_s,
                    c.carr_soln, StateName(c.carr_soln));
    h += buf;
  }
  h += "</table>\n";
}

}  // namespace hil::harness

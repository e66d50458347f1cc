#pragma once
/// @file
/// The RTK rover's state over the run (devices/zed_f9p): its timeline of carrSoln changes (none
/// 0, float 1, fixed 2) with the age of the corrections at each change, the epochs in each state
/// and the RTCM frames it received (report.json `rtk_rover`; a table in the HTML report).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hil/harness/report/svg_plot.h"

namespace hil::rtk {
class ZedF9pDevice;
}

namespace hil::harness {

struct RtkRoverChange {
  double t_s = 0;
  int carr_soln = 0;             ///< 0 none (standalone 3-D), 1 float, 2 fixed
  double correction_age_s = -1;  ///< at the change; < 0: none received
};

struct RtkRoverReport {
  std::vector<RtkRoverChange> timeline;
  std::uint64_t epochs = 0, epochs_float = 0, epochs_fixed = 0;
  std::uint64_t rtcm_frames = 0, rtcm_crc_failed = 0;
  /// Moving base (dual-antenna heading): epochs with relPosHeadingValid, the RMS and largest
  /// error of relPosHeading against the truth of the baseline, the mean accHeading.
  std::uint64_t heading_valid_epochs = 0;
  double heading_rms_error_deg = 0, heading_max_error_deg = 0, acc_heading_mean_deg = 0;
};

RtkRoverReport MakeRtkRoverReport(const rtk::ZedF9pDevice& rover);
/// The rover's figures as criterion metrics (rtk_rover.*): epochs, fixed_fraction and
/// float_fraction (of its epochs), time_to_first_float_s and time_to_first_fixed_s (the first
/// change into that state, or into fixed for float; absent when never), fixed_losses (changes
/// from fixed to a lesser state), rtcm_frames, rtcm_crc_failed; with a moving base
/// heading_valid_epochs always, and heading_rms_error_deg, heading_max_error_deg and
/// acc_heading_mean_deg when it had a valid heading (absent otherwise).
void AddRtkRoverMetrics(const std::optional<RtkRoverReport>& r,
                        std::map<std::string, std::optional<double>>& table);
nlohmann::json RtkRoverJson(const RtkRoverReport& r);
/// The HTML section: the epochs per state and the timeline as a table.
void AppendRtkRoverHtml(std::string& html, const RtkRoverReport& r);
/// The timeline as a step chart: carrSoln (0 none, 1 float, 2 fixed) from each change to the
/// next, the last state held to `end_s` (the run's emulated end).
PlotChart RtkTimelineChart(const RtkRoverReport& r, double end_s);

}  // namespace hil::harness

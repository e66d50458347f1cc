#pragma once
/// @file
/// The text sections of the sign-off report (report.html): what was tested (run_header.h), the
/// verdict at a glance with each criterion's meaning, the values to review (outside their band),
/// the faults with their effects, and what the harness measured of itself.

#include <optional>
#include <string>
#include <vector>

#include "hil/harness/report/report.h"
#include "hil/harness/report/report_html.h"
#include "hil/harness/report/run_header.h"

namespace hil::harness {

/// A heading RMSE above this many degrees is flagged for review (ours: at 5° a point 2 m ahead of
/// the reference point, an implement's hitch, moves 17 cm sideways, more than the pass-to-pass
/// budget of a row crop; a criterion on heading_rmse_deg judges it where a scenario has one).
inline constexpr double kHeadingReviewDeg = 5.0;
/// An estimate metric (RMS or percentile) more than this many times the raw fixes' same metric is
/// flagged: the default criterion fused_vs_raw's tolerance (default_criteria.h), or the bound the
/// scenario sets for it; nothing when the scenario turns it off.
inline constexpr double kWorseThanRawFactor = 1.2;

/// A value outside its band.
struct ReviewFlag {
  std::string metric;
  double value = 0;
  std::string band;     ///< the band it left, in words
  bool severe = false;  ///< the estimate is worse than claimed (red); else unusual (amber)
};

/// What a run's figures say beyond its verdict: the mean NEES outside its 99 % χ² band (above:
/// an over-confident σ, severe; below: a conservative σ), also where the scenario relaxed its
/// criterion; an RMS or percentile figure worse than the raw fixes' by more than the fused_vs_raw
/// factor; a heading RMSE above kHeadingReviewDeg.
std::vector<ReviewFlag> ReviewFlags(const RunReport& report);

/// `v` printed with a printf format ("%.3g"); an absent value is "n/a", else followed by `unit`.
std::string FormatNumber(double v, const char* format = "%.3g");
std::string FormatOptional(const std::optional<double>& v, const char* format = "%.3g",
                           const char* unit = "");

/// What a criterion's metric means, in words (empty for an unknown metric).
std::string MetricMeaning(const std::string& metric);

void AppendRunHeaderHtml(std::string& html, const RunReport& report, const RunHeader& header);
void AppendVerdictHtml(std::string& html, const RunReport& report);
void AppendReviewHtml(std::string& html, const RunReport& report);
/// The faults injected, when, how many, and their effect on the estimate (the largest horizontal
/// error from the fault's start to 10 s after its end, recovery) and, closed loop, on the path.
void AppendFaultEffectsHtml(std::string& html, const RunReport& report, const ReportSeries& series);
/// The harness's own figures: schedule error and dropped bytes per link, messages dropped,
/// lockstep lateness; virtual mode says why there is no latency or schedule error.
void AppendHarnessHtml(std::string& html, const RunReport& report, const RunHeader& header);

}  // namespace hil::harness

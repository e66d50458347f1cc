#pragma once
/// @file
/// The criteria every run is judged on unless its scenario says otherwise (section
/// `default_criteria:` of a scenario, vectors/scenarios/README.md "Default criteria"): the
/// estimate no worse than the raw GNSS fixes, a position σ that is not over-confident, solutions
/// over the whole evaluated run and, in closed loop, a controller that commands every tick. Each
/// has a key; a scenario sets the key to a number (a new bound) or to `off`.

#include <optional>
#include <string>

namespace hil::harness {

/// How a default criterion bounds its metric.
enum class DefaultBound { kMax, kRatioToBaseline };

/// One default criterion: its key, the metric it bounds, the bound and why that bound.
struct DefaultCriterionSpec {
  const char* key;
  const char* metric;
  DefaultBound kind;
  double bound;
  const char* meaning;
};

/// The default criteria, in the order the verdict lists them. The bounds' reasons:
/// - fused_vs_raw 1.2: the estimate's and the fixes' RMSE over the same window differ by chance
///   (errors correlated over seconds: a 100 s window holds some 20 independent errors of a NEO-5M
///   at 4.5 s, whose RMSE is uncertain by about 1/sqrt(2 x 20) = 16 %); 20 % above the raw fixes is
///   a worse estimate, not noise.
/// - nees_horizontal 4.0, nees_vertical 2.52: the upper end of the 99 % chi-square band of a mean
///   NEES over 10 independent samples (chi2_0.995(20) / 10 for 2 DOF, chi2_0.995(10) / 10 for 1
///   DOF). Ten is the fewest independent errors a judged window holds (errors correlated for
///   seconds, a window of tens of seconds); more would narrow the band and fail consistent
///   estimators on correlation alone. A mean NEES above the bound is an over-confident σ (by
///   sqrt(bound / DOF): 1.41x horizontally, 1.59x vertically). A conservative σ (NEES below the
///   band) is reported, not failed: it misleads no one into trusting the estimate.
/// - completeness 0.02: 2 % of the expected solutions missing (2 s of a 100 s window).
/// - controller_commanding 0: no control tick without a fresh command (not judged when a
///   controller_stop or command_link_loss fault stops the commands on purpose).
inline constexpr DefaultCriterionSpec kDefaultCriteria[] = {
    {"fused_vs_raw", "horizontal_rmse_m", DefaultBound::kRatioToBaseline, 1.2,
     "the estimate's horizontal RMSE at most this many times the raw GNSS fixes'"},
    {"nees_horizontal", "nees_horizontal_mean", DefaultBound::kMax, 4.0,
     "mean horizontal NEES (2 DOF, 2 when consistent) at most this: the reported σ is not "
     "over-confident"},
    {"nees_vertical", "nees_vertical_mean", DefaultBound::kMax, 2.52,
     "mean vertical NEES (1 DOF, 1 when consistent) at most this"},
    {"completeness", "solutions_missing_fraction", DefaultBound::kMax, 0.02,
     "at most this fraction of the expected solutions missing over the evaluated run"},
    {"controller_commanding", "closed_loop.missing_commands", DefaultBound::kMax, 0,
     "closed loop: control ticks without a fresh command at most this"},
};

/// What a scenario says of one default criterion (`default_criteria: {KEY: off | NUMBER}`).
struct DefaultCriterionSetting {
  bool off = false;
  std::optional<double> bound;  ///< replaces the default bound
};

/// The spec of `key`, or nullptr.
const DefaultCriterionSpec* FindDefaultCriterion(const std::string& key);

}  // namespace hil::harness

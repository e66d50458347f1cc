#pragma once
/// @file
/// The fault campaign's part of a run's report: what each fault injected (fault_record.h), what the
/// estimator detected (navd's `health` object in its JSON lines, estimator/include/hil/estimator/
/// navd_health.h), and how long the estimate took to recover after each fault.
///
/// report.json gains:
///   "fault_injections": [{"kind", "link", "start_s", "end_s", "unit", "count", "times_s": [...],
///                         "recovery_time_s"}],
///   "estimator_health": {"present": bool, "counters": {name: value}, "flags_seen": [...]}
/// and criteria may use the metrics
///   fault_recovery_time_s   worst recovery time over the faults (absent if one never recovers)
///   fault_injections_min    the smallest injection count over the faults (proves each was applied)
///   navd.<counter>          the last value of a navd health counter (e.g. navd.mcu_resets)
///   navd.flag.<flag>        1 when navd raised that flag at least once during the run, else 0

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hil/harness/core/json_solution_line.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/faults/fault_record.h"

namespace hil::harness {

/// navd's health as seen over a run: the last counters and every flag it raised.
struct EstimatorHealth {
  bool present = false;
  std::map<std::string, double> counters;
  std::map<std::string, double> first_counters;  ///< the counters of the first health object
  std::set<std::string> flags_seen;
  /// Takes one output line of the estimator (lines without a health object are ignored).
  void AddLine(const std::string& line);
  /// The same for a line already parsed (a JSON object; anything else is ignored).
  void AddJson(const nlohmann::json& j);
  /// The same for a line scanned instead (JsonSolutionScanner): the same counters and flags.
  void AddScanned(const JsonSolutionLine& line);
};

/// The flags navd knows (navd.flag.<name> is 0 for these when never raised).
extern const std::vector<std::string> kNavdFlags;

/// Sets each fault's recovery time: seconds from its end until the horizontal error is below
/// `threshold_m` and stays there for 2 s (0 when it never left it). Absent when no solution after
/// the end reaches that.
void ComputeRecoveryTimes(std::vector<FaultInjection>& faults,
                          const std::vector<ErrorSample>& errors, double threshold_m);

/// The same from errors added one at a time in time order, in bounded memory (a few numbers per
/// fault): a fault's recovery is known once its first run of good solutions has lasted 2 s.
class RecoveryTimeAccumulator {
 public:
  /// `faults`: the timeline's records (their start and end; FaultRecorder::records()).
  RecoveryTimeAccumulator(const std::vector<FaultInjection>& faults, double threshold_m);
  void Add(const ErrorSample& e);
  /// Sets each fault's recovery_time_s (`faults` in the order given to the constructor).
  void Apply(std::vector<FaultInjection>& faults) const;

 private:
  struct Fault {
    double end_s;
    std::optional<double> run_start_s;  // the current run of good solutions
    std::optional<double> recovery_s;
  };
  std::vector<Fault> faults_;
  double threshold_m_;
};

/// Adds fault_recovery_time_s, fault_injections_min, navd.* (see the file comment).
void AddFaultMetrics(std::map<std::string, std::optional<double>>& table,
                     const std::vector<FaultInjection>& faults, const EstimatorHealth& health);

nlohmann::json FaultInjectionsJson(const std::vector<FaultInjection>& faults);
nlohmann::json EstimatorHealthJson(const EstimatorHealth& health);

}  // namespace hil::harness

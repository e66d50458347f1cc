#pragma once
/// @file
/// What a run leaves behind: report.json (DESIGN.md contract), junit.xml (one test case per
/// criterion), and CSV files of truth, estimates and raw fixes.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/eval/outage_metrics.h"
#include "hil/harness/eval/pass_to_pass.h"
#include "hil/harness/eval/path_tracking.h"
#include "hil/harness/eval/row_deviation.h"
#include "hil/harness/faults/fault_report.h"
#include "hil/harness/links/can_bus_report.h"
#include "hil/harness/report/closed_loop_faults_report.h"
#include "hil/harness/report/link_integrity.h"
#include "hil/harness/report/rtk_rover_report.h"
#include "hil/harness/report/steering_ecu_report.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

struct LatencyStats {
  double p50_ms = 0, p99_ms = 0, max_ms = 0;
};

/// A criterion after evaluation.
struct CriterionResult {
  std::string name;
  double threshold = 0;
  std::optional<double> value;  ///< absent when the metric could not be computed (fails)
  bool pass = false;
  std::string default_key;  ///< a default criterion's key (default_criteria.h); else empty
};

/// The verdict's line for one default criterion (report.json `default_criteria`): whether this run
/// was judged on it and, when not, why.
struct DefaultCriterionStatus {
  std::string key, metric;
  /// "judged" (the default bound), "relaxed" or "tightened" (the scenario's bound), "off" (the
  /// scenario turned it off), "superseded" (the scenario's own criterion on the metric judges it),
  /// "not applicable"
  std::string status;
  std::string detail;  ///< the bound, or why it was not judged
  std::optional<double> bound;
};

/// Closed loop: what the controller and the actuator did (report.json `closed_loop`).
struct ClosedLoopReport {
  std::string controller_command, controller_exit;
  std::uint64_t control_ticks = 0, missing_commands = 0, motor_commands = 0;
  std::uint64_t saturated_commands = 0, invalid_lines = 0, command_bytes_lost = 0;
  std::optional<double> first_missing_s, last_command_s;
  std::uint64_t watchdog_trips = 0;
  /// Virtual mode: control ticks whose answer was in hand before them (no host turn of their own).
  std::uint64_t answered_ticks_without_turn = 0;
  std::optional<double> watchdog_trip_s;
  /// Real time or scaled: "lockstep" (paced virtual-mode run: the same bytes as virtual mode) or
  /// "free_running" (--free-running); "virtual" in virtual mode.
  std::string stepping = "virtual";
  /// Lockstep: actions paced, those served over 1 ms after their wall-clock time, the largest
  /// delay (a slow host holds the run back instead of changing it).
  std::uint64_t paced_actions = 0, late_actions = 0;
  double max_late_ms = 0;
  /// Distance the truth vehicle went after the last command arrived, and after the watchdog.
  std::optional<double> distance_after_last_command_m, distance_after_watchdog_m;
  double final_speed_mps = 0;
  bool stopped = false;                           ///< final speed below 1 cm/s
  std::optional<SteeringEcuReport> steering_ecu;  ///< the isobus channel's ECU
  ClosedLoopFaultsReport faults;                  ///< what the actuator faults did
};

/// Everything report.json holds.
/// A virtual run with --lockstep: how each host process was paced (report.json `lockstep`).
struct LockstepReport {
  struct Process {
    int pid = 0;
    std::string name;
    /// "emulated": on hil's clock through libhil_lockstep.so; "probe": the /proc probe paced it
    std::string clock;
  };
  std::vector<Process> processes;
  std::string fallback;     ///< why the /proc probe paced the run after all (empty: it did not)
  std::uint64_t turns = 0;  ///< times hil (or, with lookahead, a program) woke the programs
  bool lookahead = false;   ///< hil wrote ahead, the programs moved their own clock
  std::uint64_t thread_waits = 0;        ///< waits the programs' threads blocked in
  std::uint64_t descriptor_lookups = 0;  ///< fstats the library made to tell descriptors apart
  double wait_s = 0;                     ///< wall seconds hil waited for the programs (wall clock)
};

struct RunReport {
  std::string scenario;
  std::string scenario_file;
  std::uint64_t seed = 0;
  std::string mode;
  bool complete = true;               ///< false when the run stopped early
  std::vector<std::string> problems;  ///< why the run failed besides criteria (crash, silence…)
  AccuracyMetrics metrics;
  double output_rate_hz = 0;
  OutputTiming timing;
  std::optional<LatencyStats> latency;
  std::vector<OutageMetrics> outages;
  AccuracyMetrics baselines;
  std::vector<CriterionResult> criteria;
  std::vector<DefaultCriterionStatus> default_criteria;  ///< each default criterion's status
  std::string estimator_command, estimator_output, estimator_exit;
  std::string controller_command;  ///< closed loop: the controller's command (substituted)
  int estimator_pid = 0;           ///< process (and process group) id of the estimator, 0 when none
  /// Solutions dated more than 1 s before the run's start or after its end (not scored; a
  /// problem when any).
  std::size_t solutions_outside_run = 0;
  double wall_time_s = 0, sim_time_s = 0, speed = 1.0;
  int nice_requested = 0, nice = 0;  ///< the run's processes' nice value (run_priority.h)
  std::string nice_refused;          ///< why the nice value asked for was not granted
  /// Real time and scaled: wall seconds from the estimator's start until it had opened every
  /// serial link it reads (the run's clock starts then; run_prepare.cc AwaitHostLinksOpen).
  std::optional<double> host_open_wait_s;
  std::uint64_t gnss_bytes = 0, gnss_messages_dropped = 0;
  std::uint64_t fault_messages_dropped = 0, fault_bytes_corrupted = 0;
  /// Lines of the estimator's output that were valid records of its format but no solution
  /// (NMEA: RMC, GSA, GSV, a GGA without a fix...): counted, not warned about.
  std::size_t estimator_other_records = 0;
  std::vector<std::pair<std::string, std::string>>
      faults;  ///< {kind, "start–end s"} for the report
  std::vector<FaultInjection>
      fault_injections;              ///< per fault: what was injected, recovery (fault_report.h)
  EstimatorHealth estimator_health;  ///< navd's detections (fault_report.h)
  std::string
      incomplete_reason;  ///< why the run stopped early (signal, output folder, link), if it did
  /// The signal (SIGINT, SIGTERM, SIGHUP) that interrupted the run, 0 when none (report.json
  /// `interrupted_by`; `hil run` then exits 128 + the signal).
  int interrupt_signal = 0;
  /// The first file of the run folder that could not be written and why (report.json
  /// `write_failure`; `hil run` then exits kExitWriteFailure), empty when every file was.
  std::string write_failure;
  std::optional<CanBusReport> can;          ///< the scenario's CAN bus (can_run.h), when it has one
  std::optional<TrackingMetrics> tracking;  ///< closed loop: the truth against the path
  /// closed loop: pass-to-pass cross-track error, ISO 12188-2 style (report.json `pass_to_pass`)
  std::optional<PassToPassMetrics> pass_to_pass;
  std::optional<ClosedLoopReport> closed_loop;  ///< closed loop: controller and actuator
  /// closed loop: each fault's effect on the path tracking (report.json `tracking.faults`)
  std::vector<FaultPathDeviation> tracking_faults;
  std::optional<RowDeviation> row_following;  ///< closed loop in a greenhouse (paper 001)
  /// The RTK rover's state timeline (report.json `rtk_rover`), when the scenario has one.
  std::optional<RtkRoverReport> rtk_rover;
  /// What the estimator says it received against what was sent (link_integrity.h).
  std::vector<LinkIntegrity> link_integrity;
  /// Real time: each real-time thread's scheduling and the CPU it used (run_outputs.h).
  std::vector<std::pair<std::string, link::ThreadSchedule>> realtime_threads;
  std::optional<LockstepReport> lockstep;  ///< virtual mode with --lockstep
  bool pass() const;
};

/// Metric name → value (absent when not computable), the names criteria use (kCriterionMetrics).
using MetricTable = std::map<std::string, std::optional<double>>;
MetricTable AccuracyTable(const AccuracyMetrics& m);
/// Every criterion metric of a run (accuracy, timing, outages, consistency).
MetricTable RunMetricTable(const RunReport& r);

/// Escapes text for XML and HTML (attributes and content): < > & ".
std::string XmlEscape(const std::string& s);

/// The default criteria (default_criteria.h) that judge this run, as criteria, after the
/// scenario's; `status` gets one line per default criterion. A default applies unless the scenario
/// turns it off or has its own criterion on the same metric (of the same kind: a ratio to the
/// baseline for fused_vs_raw), and only where its metric exists: fused_vs_raw with raw fixes in the
/// evaluated window, the NEES with a position σ reported, controller_commanding in closed loop
/// without a controller_stop or command_link_loss fault.
std::vector<Criterion> DefaultCriteriaFor(const Scenario& scenario, const RunReport& report,
                                          std::vector<DefaultCriterionStatus>& status);

/// Evaluates the scenario's criteria against the metrics.
std::vector<CriterionResult> EvaluateCriteria(const std::vector<Criterion>& criteria,
                                              const MetricTable& metrics,
                                              const MetricTable& baselines);
std::vector<CriterionResult> EvaluateCriteria(const std::vector<Criterion>& criteria,
                                              const AccuracyMetrics& metrics,
                                              const AccuracyMetrics& baselines);

/// Writes report.json. @throws std::runtime_error naming the file on failure.
void WriteReportJson(const RunReport& report, const std::string& path);
/// Writes junit.xml. @throws std::runtime_error naming the file on failure.
void WriteJunitXml(const RunReport& report, const std::string& path);
/// Writes errors (time, truth and estimate ENU, errors) as CSV.
void WriteErrorsCsv(const std::vector<ErrorSample>& errors, const std::string& path);
/// That CSV's header line and the line of one error (written as the run goes: run_scoring.h).
void AppendErrorsCsvHeader(std::string& text);
void AppendErrorsCsvRow(std::string& text, const ErrorSample& e);

}  // namespace hil::harness

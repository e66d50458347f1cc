#pragma once
// The phases of RunScenario (run_context.h), in order. Each reads and fills the run's context.

#include "hil/harness/report/report_html.h"
#include "hil/harness/run/run_context.h"
#include "hil/harness/run/run_folder.h"
#include "hil/harness/run/run_watchdog.h"

namespace hil::harness {

/// The run folder's captures/, the report's header, the devices and their links, navd.conf, the
/// process under test and the reader of its output. @throws std::runtime_error for setup failures.
void Prepare(RunContext& ctx);
/// The engine from t = 0 to the end (or an early stop), watched by `watchdog`; then the bytes
/// still queued and the captures go out.
void Execute(RunContext& ctx, RunWatchdog& watchdog);
/// The host reads every byte and its output is complete (or it hangs, or the run is stopped).
void Drain(RunContext& ctx);
/// Stops the process under test and reports a crash, a hang or an early stop.
void StopEstimator(RunContext& ctx);

/// The run's scoring (run_scoring.h), started with the engine: it asks ctx.truth_builder.
void StartScoring(RunContext& ctx);

/// What the evaluation computed that the run folder's files need.
struct RunEvaluation {
  TruthTable truth;  ///< closed loop: the whole truth.csv grid (open loop: the run's last samples)
  ReportSeries series;
};
/// What report.html's header says was tested, and the harness's own figures (run_header.cc).
RunHeader MakeRunHeader(const RunContext& ctx);
/// Metrics, baselines, timing, outages, counters, fault injections and criteria into ctx.report.
RunEvaluation Evaluate(RunContext& ctx);
/// The run folder: CSVs, schedule errors, report.html, junit.xml and report.json last (written
/// even when another file cannot be).
void WriteRunFolder(RunContext& ctx, RunEvaluation& evaluation);

}  // namespace hil::harness

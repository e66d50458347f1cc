#include "hil/harness/run/run.h"

#include <cmath>
#include <cstdio>

#include "hil/harness/run/run_context.h"
#include "hil/harness/run/run_guard.h"
#include "hil/harness/run/run_watchdog.h"

#include "run_phases.h"

namespace hil::harness {

std::string ModeName(RunMode mode, double speed) {
  if (mode == RunMode::kVirtual) return "virtual";
  return std::abs(speed - 1.0) < 1e-12 ? "realtime" : "scaled";
}

std::string Substitute(const std::string& text,
                       const std::vector<std::pair<std::string, std::string>>& vars) {
  std::string out = text;
  for (const auto& [key, value] : vars) {
    const std::string pattern = "{" + key + "}";
    for (std::size_t pos = 0; (pos = out.find(pattern, pos)) != std::string::npos;
         pos += value.size()) {
      out.replace(pos, pattern.size(), value);
    }
  }
  return out;
}

RunReport RunScenario(const Scenario& scenario, const RunOptions& options) {
  // Ctrl-C / SIGTERM: stop the estimator, write an incomplete report. Made before the context
  // and gone after it: the captures' last writes (the endpoints' destructors) happen under it.
  const InterruptGuard interrupt_guard;
  RunContext ctx(scenario, options);
  ClearWriteFailures();
  // before the run's threads and hosts start: they inherit it
  const RunPriority priority = SetProcessNice(options.nice);
  ctx.report.nice_requested = priority.requested;
  ctx.report.nice = priority.nice;
  ctx.report.nice_refused = priority.refused;
  if (!priority.refused.empty())
    std::fprintf(stderr,
                 "hil: nice %d not granted (%s; it needs CAP_SYS_NICE or RLIMIT_NICE): the run "
                 "goes on at nice %d (--nice 0 asks for nothing)\n",
                 options.nice, priority.refused.c_str(), priority.nice);
  Prepare(ctx);
  RunWatchdog watchdog(ctx);
  Execute(ctx, watchdog);
  Drain(ctx);
  StopEstimator(ctx);
  RunEvaluation evaluation = Evaluate(ctx);
  WriteRunFolder(ctx, evaluation);
  return ctx.report;
}

}  // namespace hil::harness

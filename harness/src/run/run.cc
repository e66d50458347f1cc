#include "hil/harness/run/run.h"

#include <cmath>
#include <cstdio>

#include "hil/harness/dut/group_reaper.h"
#include "hil/harness/run/folder_lock.h"
#include "hil/harness/run/run_context.h"
#include "hil/harness/run/run_guard.h"
#include "hil/harness/run/run_watchdog.h"

#include "run_phases.h"

namespace hil::harness {

std::string ModeName(RunMode mode, double speed) {
  if (mode == RunMode::kVirtual) return "virtual";
  return std::abs(speed - 1.0) < 1e-12 ? "realtime" : "scaled";
}

RunReport RunScenario(const Scenario& scenario, const RunOptions& options) {
  // Ctrl-C / SIGTERM: stop the estimator, write an incomplete report. Made before the context
  // and gone after it: the captures' last writes (the endpoints' destructors) happen under it.
  const InterruptGuard interrupt_guard;
  // the folder, locked; the reaper (forked here, before the run's threads) keeps the lock until
  // every process the run started has ended, even when hil is killed (group_reaper.h)
  MakeRunFolder(options.out_dir);
  const FolderLock lock(options.out_dir, kRunLockName);
  GroupReaper reaper(lock.fd());
  RunContext ctx(scenario, options);
  ctx.reaper = &reaper;
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
  if (ctx.estimator) reaper.Release(ctx.estimator->pid());
  RunEvaluation evaluation = Evaluate(ctx);
  WriteRunFolder(ctx, evaluation);
  return ctx.report;
}

}  // namespace hil::harness

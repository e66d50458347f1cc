// Phases 2 and 3 of a run: the engine executes the scenario; the drain lets the host finish.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "hil/harness/core/machine_load.h"
#include "hil/harness/dut/process_group.h"
#include "hil/harness/engine/clocked_host_turns.h"
#include "hil/harness/engine/virtual_host_turns.h"
#include "hil/harness/report/run_outputs.h"

#include "run_phases.h"

namespace hil::harness {
namespace {

constexpr double kDrainQuietS = 0.5;  // estimator output quiet this long after the last byte: done
// virtual mode: the most bytes one link may hold unread by the host (the order across links is
// VirtualGate's: before one link's bytes, the others are read to the last byte)
constexpr std::size_t kLinkBacklogBytes = 2048;
// ... and when the host merges its inputs by device time (the links run apart by up to half its
// merge window, RunContext::navd_merge_window_s): about 2 s of IMU frames at 100 Hz
constexpr std::size_t kSkewLinkBacklogBytes = 16384;
// virtual mode's drain: the estimator's whole process group asleep, with nothing left to read,
// in this many consecutive checks this far apart, has finished its output
constexpr int kIdleChecks = 3;
constexpr useconds_t kIdleCheckUs = 1000;

// --lockstep: how long (wall) the host processes may take to load the library before the /proc
// probe paces them instead (as VirtualGate::kHostStartLimit, a loaded machine's start-up).
constexpr Duration kPreloadAttachLimit = std::chrono::seconds(6);

// --lockstep: whether the estimator's process group and the controller have loaded the library.
bool HostsAttached(const RunContext& ctx) {
  const int controller = ctx.controller ? ctx.controller->pid() : 0;
  bool estimator = false, controller_attached = controller == 0;
  for (const auto& p : ctx.shared_clock->Processes()) {
    if (p.pid == controller) controller_attached = true;
    if (p.pid != controller && getpgid(p.pid) == ctx.estimator->pid()) estimator = true;
  }
  return estimator && controller_attached;
}

// --lockstep: the host processes on hil's clock (clocked_host_turns.h) once they have loaded the
// library; null (and the library told to pass every call through) when one has not in time.
std::unique_ptr<HostTurns> MakeClockedTurns(RunContext& ctx, RunWatchdog& watchdog) {
  ctx.report.lockstep.emplace();
  const WallTime start = WallNow();
  while (!HostsAttached(ctx)) {
    if (!ctx.EstimatorRunning() || WallNow() - start > kPreloadAttachLimit) {
      ctx.report.lockstep->fallback =
          "a host process did not load libhil_lockstep.so within " +
          SecondsText(ToSeconds(kPreloadAttachLimit)) +
          " s (a static binary, or the program ended): the /proc probe paced the run";
      std::fprintf(stderr, "hil: --lockstep: %s\n", ctx.report.lockstep->fallback.c_str());
      ctx.shared_clock->Abandon();
      return nullptr;
    }
    usleep(1000);
  }
  ctx.clocked = true;
  auto pacer = std::make_unique<ClockedPacer>();
  ClockedPacer& clocked = *pacer;
  ctx.pacer = std::move(pacer);
  if (ctx.scenario.closed_loop.enabled && ctx.set.can && ctx.set.steering)
    ctx.set.can->set_stamp_at_turns(true);
  // lookahead: nothing a program does may reach a device (lookahead_writer.h)
  const bool lookahead =
      ctx.options.lockstep_lookahead && !ctx.scenario.closed_loop.enabled && !ctx.set.can;
  auto turns = std::make_unique<ClockedHostTurns>(
      *ctx.shared_clock, clocked,
      [&watchdog](std::size_t busy, bool new_wait) {
        return watchdog.OnLockstepWait(busy, new_wait);
      },
      lookahead);
  ctx.clocked_turns = turns.get();
  return turns;
}

// Virtual mode (or lockstep) with an estimator: host turns, and a gate through which the host
// sees its links' bytes in emulated-time order (virtual_gate.h); a wait that sees no byte read for
// the silence timeout ends the run as a hang or a closed port (RunWatchdog::OnGateWait). Free
// running, or no host: the hosts are read after every event.
std::unique_ptr<HostTurns> MakeHostTurns(RunContext& ctx, RunWatchdog& watchdog) {
  if (ctx.pacer->stepping() == Stepping::kFreeRunning || ctx.options.emulate_only)
    return std::make_unique<NoHostTurns>();
  if (ctx.shared_clock && ctx.estimator) {
    if (std::unique_ptr<HostTurns> turns = MakeClockedTurns(ctx, watchdog)) return turns;
  }
  std::vector<SerialEndpoint*> read_by_host;
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports) {
      if (ctx.HostReads(*ep)) read_by_host.push_back(ep.get());
    }
  }
  const Duration skew = TimeFromSeconds(ctx.navd_merge_window_s / 2) - Time{};
  ctx.gate.emplace(
      read_by_host, skew > Duration{0} ? kSkewLinkBacklogBytes : kLinkBacklogBytes,
      [&watchdog](std::size_t unread, bool new_wait) {
        return watchdog.OnGateWait(unread, new_wait);
      },
      ctx.estimator->pid(), skew);
  ctx.pacer->UseGate(*ctx.gate);
  // closed loop: every control tick is a host turn (lockstep with the controller)
  Duration control_period{};
  if (ctx.scenario.closed_loop.enabled) {
    control_period = DurationFromSeconds(ctx.scenario.closed_loop.control_period_s);
    // the controller's frames on a bus: stamped at the turn that hands them to the ECU
    if (ctx.set.can && ctx.set.steering) ctx.set.can->set_stamp_at_turns(true);
  }
  return std::make_unique<VirtualHostTurns>(*ctx.gate, control_period);
}

// Bytes not yet read on the links the estimator reads (none named: all).
std::size_t UnreadByHost(const RunContext& ctx) {
  std::size_t n = 0;
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports) {
      if (ctx.HostReads(*ep)) n += ep->PendingToHost();
    }
  }
  return n;
}

// Real time: waits while the host reads, up to the silence timeout without progress.
void DrainInputRealtime(RunContext& ctx) {
  WallTime last_progress = WallNow();
  std::size_t pending = UnreadByHost(ctx);
  while (ctx.EstimatorRunning() && pending > 0 && WallNow() - last_progress < ctx.silence &&
         !ctx.Interrupted()) {
    usleep(5000);
    ctx.collector->Poll();
    const std::size_t p = UnreadByHost(ctx);
    if (p < pending) last_progress = WallNow();
    pending = p;
  }
}

// Output complete: in virtual mode, when every process of the estimator's group has slept through
// a few checks with all its input read (it waits for input that will not come); otherwise (real
// time, or /proc cannot tell) when its output has been quiet for kDrainQuietS.
void DrainOutput(RunContext& ctx) {
  const WallTime drain_start = WallNow();
  GroupActivity before;
  std::optional<WallTime> output_before;
  int idle_checks = 0;
  while (ctx.EstimatorRunning() && !ctx.Interrupted()) {
    ctx.collector->Poll();
    const WallTime last_output = ctx.collector->last_output_wall();
    const bool any_output = last_output > WallTime{};
    if (ctx.clocked && any_output) {
      // on hil's clock: the programs say themselves when every thread waits
      const bool idle = ctx.shared_clock->Idle() && last_output == output_before;
      idle_checks = idle ? idle_checks + 1 : 0;
      output_before = last_output;
      if (idle_checks >= kIdleChecks) break;
    } else if (ctx.gate && any_output) {
      const GroupActivity now = ReadGroupActivity(ctx.estimator->pid());
      const bool idle =
          SleptThroughout(before, now) && last_output == output_before && ctx.gate->Unread() == 0;
      idle_checks = idle ? idle_checks + 1 : 0;
      before = now;
      output_before = last_output;
      if (idle_checks >= kIdleChecks) break;
    }
    const Duration quiet = WallNow() - std::max(last_output, drain_start);
    if (any_output && quiet > DurationFromSeconds(kDrainQuietS)) break;
    if (quiet > ctx.silence) {
      if (ctx.collector->solutions() == 0)
        ctx.hang = "no output for " + SecondsText(ctx.silence_s) + " s";
      break;
    }
    // an estimator that keeps talking once its input is read has had the silence timeout to end
    if (WallNow() - drain_start > ctx.silence) break;
    usleep(ctx.gate || ctx.clocked ? kIdleCheckUs : 10000);
  }
}

// The last line of a file that holds more than white space, at most 200 characters ("" if none).
std::string LastLine(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last.size() > 200 ? last.substr(0, 200) + "..." : last;
}

// Closed loop: a controller that ended by itself before the scenario did left the vehicle
// unguided (`exec: guidanced: not found` ends it at once): a problem, never a pass. One that hil
// ended (the controller_stop fault) is the scenario's doing.
void NoteControllerEnded(RunContext& ctx) {
  if (!ctx.controller || ctx.options.emulate_only || ctx.stop_reason || ctx.hang) return;
  if (ctx.controller->Running() || ctx.controller->Describe() == "killed by hil") return;
  const std::string last = LastLine(ctx.dir + "/controller.log");
  ctx.report.problems.push_back(
      "the controller ended before the scenario did: " + ctx.controller->Describe() +
      (last.empty() ? " (controller.log is empty)"
                    : " (controller.log's last line: \"" + last + "\")"));
}

}  // namespace

void Execute(RunContext& ctx, RunWatchdog& watchdog) {
  const Scenario& scenario = ctx.scenario;
  ctx.byte_faults.emplace(scenario.faults, ctx.seed, &ctx.fault_recorder);
  ctx.progress.emplace(ctx.options.progress);
  // the turns first: --lockstep chooses the pacer there
  std::unique_ptr<HostTurns> turns = MakeHostTurns(ctx, watchdog);
  ctx.engine.emplace(EngineDevices{ctx.set.devices, ctx.set.endpoints, ctx.set.can.get(),
                                   ctx.set.base, ctx.set.steering},
                     *ctx.pacer, std::move(turns), ctx.t_end);
  ctx.engine->set_byte_faults(&*ctx.byte_faults);
  ctx.engine->set_recorder(&ctx.fault_recorder);
  ctx.baseline.emplace(ctx.set, &ctx.fault_recorder, ctx.fixes_csv);
  if (scenario.estimator.output == EstimatorOutput::kN2kSocketcan) {
    Engine& engine = *ctx.engine;
    engine.KeepBusFramesForCollector();
    ctx.collector->AttachBus([&engine] { return engine.TakeBusFramesForCollector(); },
                             scenario.start_utc);
  }
  // the truth for the evaluation, sampled on a thread of its own as the run goes (truth_table.h)
  ctx.truth_builder.emplace(scenario.truth);
  StartScoring(ctx);  // asks the builder for truth.csv's times as the run goes
  // the run's own samples serve the times they have (closed loop: the builder's integrator obeys
  // the run's commands for the times they miss)
  ctx.engine->set_truth_tap(
      [&builder = *ctx.truth_builder](const TruthSample& s) { builder.Offer(s); });
  ctx.engine->set_command_tap([&builder = *ctx.truth_builder](const VehicleCommand& c, bool late) {
    builder.Command(c, late);
  });
  ctx.set.cpu_at_start = ReadCpuTicks();  // what the machine gave a real-time run from here on
  try {
    ctx.engine->Run(watchdog, &scenario.truth);
  } catch (const std::exception& e) {
    ctx.stop_reason =
        std::string("the run failed at t = ") + SecondsText(ctx.t_now) + " s: " + e.what();
  }
  if (!ctx.hang && !ctx.Interrupted()) ctx.engine->Flush();
  ctx.set.threads = ctx.pacer->threads();
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports) ep->FlushCapture();
  }
  ctx.Interrupted();  // a capture that could not be written stops the run here at the latest
}

void Drain(RunContext& ctx) {
  if (ctx.Healthy()) {
    if (ctx.gate) {
      ctx.gate->WaitAllRead();  // gives up (hang, closed port, interrupt) through its wait step
    } else if (ctx.clocked) {
      // Engine::Flush's last turn had the programs read everything
    } else {
      DrainInputRealtime(ctx);
    }
  }
  if (ctx.Healthy()) DrainOutput(ctx);
}

namespace {

// --lockstep: which way each host process ran, and what the shared clock cost.
void NoteLockstep(RunContext& ctx) {
  if (!ctx.shared_clock || !ctx.report.lockstep) return;
  LockstepReport& r = *ctx.report.lockstep;
  if (ctx.clocked) {
    for (const auto& p : ctx.shared_clock->Processes())
      r.processes.push_back({p.pid, p.name, "emulated"});
  } else {
    if (ctx.estimator) r.processes.push_back({ctx.estimator->pid(), "estimator", "probe"});
    if (ctx.controller) r.processes.push_back({ctx.controller->pid(), "controller", "probe"});
  }
  const lockstep::LockstepHost::Stats s = ctx.shared_clock->stats();
  r.turns = s.grants;
  r.lookahead = ctx.clocked_turns && ctx.clocked_turns->lookahead();
  r.thread_waits = s.thread_waits;
  r.descriptor_lookups = s.descriptor_lookups;
  r.wait_s = ToSeconds(s.wait);
}

}  // namespace

void StopEstimator(RunContext& ctx) {
  NoteLockstep(ctx);
  RunReport& report = ctx.report;
  ctx.progress->Finish();
  const bool crashed =
      !ctx.options.emulate_only && !ctx.hang && !ctx.stop_reason && !ctx.EstimatorRunning();
  NoteControllerEnded(ctx);
  const ExitInfo exit_info = ctx.estimator ? ctx.estimator->Stop() : ExitInfo{};
  ctx.collector->Poll();
  report.estimator_exit = ctx.estimator ? exit_info.Describe() : "none (emulator only)";
  if (crashed) {
    report.problems.push_back("the estimator ended before the scenario did: " +
                              exit_info.Describe() + " (see estimator.stderr)");
    report.complete = false;
  }
  if (ctx.hang) {
    report.problems.push_back("the estimator hung: " + *ctx.hang + "; it was stopped (" +
                              exit_info.Describe() + ")");
    report.complete = false;
  }
  if (ctx.stop_reason) {
    report.problems.push_back("the run stopped early: " + *ctx.stop_reason +
                              "; the estimator was stopped (" + exit_info.Describe() + ")");
    report.complete = false;
    std::fprintf(stderr, "hil: %s; the estimator was stopped, the report is marked incomplete\n",
                 ctx.stop_reason->c_str());
  }
  if (!report.complete && !report.problems.empty())
    report.incomplete_reason = report.problems.front();
  // a run stopped early simulated up to its last event: the report says so, and nothing after it
  // (the scenario's truth beyond the stop, a closed loop's path not driven) is scored
  if (crashed || ctx.hang || ctx.stop_reason) {
    ctx.t_end = std::min(ctx.t_end, ctx.t_now);
    report.sim_time_s = ToSeconds(ctx.t_end);
  }
}

}  // namespace hil::harness

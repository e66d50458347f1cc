// Phase 1 of a run: the folder, the report's header, the devices and links, the process under test.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "hil/harness/devices/device_kind.h"
#include "hil/harness/devices/navd_conf.h"
#include "hil/harness/dut/shell_substitute.h"
#include "hil/harness/engine/clocked_pacer.h"
#include "hil/harness/engine/lockstep_pacer.h"
#include "hil/harness/engine/wall_clock_pacer.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/run/can_run.h"

#include "run_phases.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr const char* kNavLink = "ttyNAV";  // pty the estimator writes NMEA into (output nmea_pty)
// Virtual mode: navd's [input] merge_window_s. The gate lets its links run apart by half of it,
// which leaves the other half for a GNSS epoch's bytes to be made after its time of validity
// (RTK NMEA at 115200 Bd: tens of ms; a NEO-5M's epoch at 9600 Bd: about 0.5 s).
constexpr double kNavdMergeWindowS = 2.0;
constexpr useconds_t kHostOpenPollUs = 2000;  // how often the start checks the host's opens

// The links the estimator reads: those named in its command ({ttyGPS}) or, for navd, those the
// device table's rows say navd reads in its mode (navd.conf names them).
std::set<std::string> HostLinks(const Scenario& s, const std::string& raw_command,
                                const DeviceSet& set) {
  std::set<std::string> used;
  for (const auto& [name, path] : set.links) {
    if (raw_command.find("{" + name + "}") != std::string::npos) used.insert(name);
  }
  if (raw_command.find("{navd}") == std::string::npos) return used;
  for (const DeviceKind* k : DeviceKinds()) {
    if (!k->navd_links) continue;
    for (const std::string& link : k->navd_links(s)) used.insert(link);
  }
  return used;
}

// A closed loop's controller reads its links in the lockstep too: the actuators' replies and
// status (released at host turns) are read before the next sensor bytes reach the estimator, so
// which of them the controller has seen when a solution comes does not depend on the machine
// (paper 001's rangefinders and base; the ISOBUS steering ECU's status on ttyCAN, whose exit and
// reset request, read after the solution in some loaded runs, sent "not intended to steer" one
// command late). The links only the controller reads leave the gate when it ends
// (RunContext::ControllerGone).
void AddControllerLinks(RunContext& ctx) {
  const ClosedLoopSpec& c = ctx.scenario.closed_loop;
  if (!c.enabled || ctx.options.emulate_only) return;
  const bool all = ctx.host_links.empty();  // the estimator reads every link
  for (const auto& [name, path] : ctx.set.links) {
    if (c.controller.find("{" + name + "}") == std::string::npos) continue;
    if (!all && ctx.host_links.count(name)) continue;  // the estimator reads it too
    ctx.controller_links.insert(name);
  }
  if (!all) ctx.host_links.insert(ctx.controller_links.begin(), ctx.controller_links.end());
}

// The captures note a failed write in the run's diagnostics (those that failed while the devices
// were built, at once).
void ReportCaptureFailuresTo(DeviceSet& set, RunDiagnostics& diagnostics) {
  for (const auto& ports : set.endpoints) {
    for (const auto& ep : ports) ep->ReportWriteFailuresTo(&diagnostics);
  }
  if (set.can) set.can->ReportWriteFailuresTo(&diagnostics);
}

void MakeCapturesFolder(const RunContext& ctx) {
  CheckCanRunMode(ctx.scenario, ctx.options);
  fs::create_directories(ctx.dir + "/captures");
}

void StartReport(RunContext& ctx) {
  const Scenario& scenario = ctx.scenario;
  RunReport& report = ctx.report;
  report.scenario = scenario.name;
  report.scenario_file = scenario.file;
  report.seed = ctx.seed;
  report.mode = ModeName(ctx.options.mode, ctx.options.speed);
  report.speed = ctx.options.mode == RunMode::kVirtual ? 1.0 : ctx.options.speed;
  report.sim_time_s = scenario.duration_s;
  report.estimator_output = std::string(Name(scenario.estimator.output));
  for (const Fault& f : scenario.faults.faults) {
    report.faults.emplace_back(FaultKindName(f.kind), SecondsText(f.start) + "-" +
                                                          SecondsText(f.end) + " s" +
                                                          (f.link.empty() ? "" : " on " + f.link));
  }
}

// The estimator's command with every {key} substituted; opens the pty of output nmea_pty.
std::string EstimatorCommand(RunContext& ctx, const std::string& raw_command) {
  std::vector<std::pair<std::string, std::string>> vars{
      {"navd", ctx.options.navd_path}, {"run_dir", ctx.dir}, {"seed", std::to_string(ctx.seed)}};
  vars.insert(vars.end(), ctx.set.links.begin(), ctx.set.links.end());
  if (ctx.scenario.estimator.output == EstimatorOutput::kNmeaPty && !ctx.options.emulate_only) {
    ctx.nav_pty = std::make_unique<link::PtyPort>(ctx.dir + "/" + kNavLink, 115200);
    vars.emplace_back(kNavLink, ctx.dir + "/" + kNavLink);
  }
  return Substitute(raw_command, vars);
}

// --lockstep: the shell line's exports that preload the library into the host's programs.
std::string HostShellPrefix(const RunContext& ctx) {
  return ctx.shared_clock ? ctx.shared_clock->ShellExports(ctx.preload_library) : "";
}

// --lockstep (virtual mode): the shared clock's file in the run folder, before the hosts start.
void MakeSharedClock(RunContext& ctx) {
  if (!ctx.options.lockstep || ctx.options.mode != RunMode::kVirtual || ctx.options.emulate_only)
    return;
  ctx.preload_library = lockstep::FindPreloadLibrary();
  if (ctx.preload_library.empty())
    throw std::runtime_error(
        "--lockstep: libhil_lockstep.so is neither beside hil nor in ../lib/hil/preload (build the "
        "hil_harness_preload target, or install hil)");
  ctx.shared_clock.emplace(ctx.dir + "/lockstep.shm", ToNs(ctx.scenario.start_utc));
  // a thread waiting only on links hil did not touch sleeps through a grant
  ctx.shared_clock->SetLinks(ClockedPacer::LinkDevices(ctx.set.endpoints));
}

void StartEstimator(RunContext& ctx, const std::string& command) {
  if (ctx.options.emulate_only) {
    for (const auto& [name, path] : ctx.set.links) {
      std::printf("%s %s\n", name.c_str(), path.c_str());
    }
    std::fflush(stdout);
    return;
  }
  ctx.estimator.emplace(command, ctx.dir + "/estimator.stderr", HostShellPrefix(ctx));
  ctx.report.estimator_pid = ctx.estimator->pid();
  if (ctx.reaper) ctx.reaper->Watch(ctx.estimator->pid());  // its group dies with hil
  // time for the program to open its devices (gpsd flushes a tty's input when it opens it)
  if (ctx.scenario.estimator.startup_s > 0)
    usleep(static_cast<useconds_t>(ctx.scenario.estimator.startup_s * 1e6));
}

// Real time and scaled: a UART sends whether anyone listens, so the bytes of a link the host has
// not opened yet are lost (SerialEndpoint::WriteNextByte). The run's clock starts once the host
// has opened every serial link it reads, so a slow start (a cold cache, a loaded machine, 20x
// speed) loses no epoch. Gives up after the silence timeout, or when the estimator ended; what
// then goes unread is captured as drops and judged as such.
void AwaitHostLinksOpen(RunContext& ctx) {
  const WallTime start = WallNow();
  for (;;) {
    bool all_open = true;
    for (const auto& ports : ctx.set.endpoints) {
      for (const auto& ep : ports) {
        if (ctx.HostReads(*ep) && !ep->HostAttached()) all_open = false;
      }
    }
    const double waited_s = ToSeconds(WallNow() - start);
    ctx.report.host_open_wait_s = waited_s;
    if (all_open || !ctx.EstimatorRunning() || ctx.Interrupted()) return;
    if (WallNow() - start > ctx.silence) {
      ctx.report.problems.push_back("the estimator had not opened every link it reads " +
                                    SecondsText(waited_s) +
                                    " s after it started: the run began without it");
      return;
    }
    usleep(kHostOpenPollUs);
  }
}

// Closed loop: the FIFO navd writes its NMEA solution into, held open (read and write) by the run
// so that navd's non-blocking open finds a reader and the controller's open finds a writer.
void MakeFifo(const std::string& path, OwnedFd& held) {
  unlink(path.c_str());
  if (mkfifo(path.c_str(), 0600) != 0)
    throw std::runtime_error("cannot make the FIFO " + path + ": " + std::strerror(errno));
  held.fd = open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (held.fd < 0)
    throw std::runtime_error("cannot open the FIFO " + path + ": " + std::strerror(errno));
}

// ... and with navd_mode gyro_odometry the FIFO the controller forwards the base's encoder counts
// into for navd ({odometry_fifo}).
void MakeNavFifo(RunContext& ctx) {
  if (!ctx.scenario.closed_loop.enabled || ctx.options.emulate_only) return;
  MakeFifo(ctx.dir + "/" + kNavNmeaFifo, ctx.nav_fifo);
  if (ctx.scenario.estimator.navd_mode == NavdMode::kGyroOdometry)
    MakeFifo(ctx.dir + "/" + kOdometryFifo, ctx.odometry_fifo);
}

// Closed loop: the controller, in the estimator's process group.
void StartController(RunContext& ctx) {
  const ClosedLoopSpec& c = ctx.scenario.closed_loop;
  if (!c.enabled || ctx.options.emulate_only || !ctx.estimator) return;
  const truth::Geodetic& o = ctx.scenario.truth.origin;
  char origin[96];
  std::snprintf(origin, sizeof origin, "%.9f,%.9f,%.3f", o.lat_deg, o.lon_deg, o.height_m);
  // the UTC time of day (s) of emulated t = 0, when the devices' first periods begin
  const std::int64_t tod_ns = ((ToNs(ctx.scenario.start_utc) % kDayNs) + kDayNs) % kDayNs;
  char start_tod[32];
  std::snprintf(start_tod, sizeof start_tod, "%lld.%09lld",
                static_cast<long long>(tod_ns / 1'000'000'000LL),
                static_cast<long long>(tod_ns % 1'000'000'000LL));
  std::vector<std::pair<std::string, std::string>> vars{
      {"start_tod", start_tod},
      {"guidanced", ctx.options.guidanced_path},
      {"path_file", c.path_file},
      {"nav_nmea", ctx.dir + "/" + kNavNmeaFifo},
      {"origin", origin},
      {"run_dir", ctx.dir},
      {"seed", std::to_string(ctx.seed)},
      {"odometry_fifo", ctx.dir + "/" + kOdometryFifo}};
  vars.insert(vars.end(), ctx.set.links.begin(), ctx.set.links.end());
  const std::string command = Substitute(c.controller, vars);
  ctx.report.controller_command = command;
  ctx.controller.emplace(command, ctx.estimator->pid(), ctx.dir + "/controller.log",
                         HostShellPrefix(ctx));
}

}  // namespace

void Prepare(RunContext& ctx) {
  const Scenario& scenario = ctx.scenario;
  const RunOptions& opt = ctx.options;
  MakeCapturesFolder(ctx);
  StartReport(ctx);
  ctx.set = BuildDevices(scenario, ctx.seed, ctx.dir);
  ReportCaptureFailuresTo(ctx.set, ctx.diagnostics);
  const std::string raw_command = opt.estimator_command.value_or(scenario.estimator.command);
  // virtual mode: navd merges its inputs by device time, so the gate may hand the links over in
  // batches (virtual_gate.h, input_merge.h); a scenario's own merge_window_s is kept as it is. Not
  // in a closed loop: the merge holds navd's solutions back by the window, and the controller
  // steers from them.
  // Nor in navd's UWB mode: it does not merge by device time (the WT901C's packets carry no time;
  // it fuses the latest heading and the rates read since the last fix), so its links must reach
  // it in emulated-time order, or which WT901C packets a fix sees depends on when navd woke
  // between two links' writes (same-seed runs then differed by millimetres).
  const double own_window_s = NavdMergeWindowS(scenario);
  const bool navd_virtual = opt.mode == RunMode::kVirtual && !opt.emulate_only &&
                            !scenario.closed_loop.enabled &&
                            scenario.estimator.navd_mode != NavdMode::kUwb &&
                            raw_command.find("{navd}") != std::string::npos;
  ctx.navd_merge_window_s =
      own_window_s >= 0 ? own_window_s : (navd_virtual ? kNavdMergeWindowS : 0.0);
  if (!navd_virtual) ctx.navd_merge_window_s = 0;
  WriteNavdConfig(ctx.dir + "/navd.conf", scenario, ctx.dir + "/" + scenario.gnss.link,
                  navd_virtual && own_window_s < 0 ? kNavdMergeWindowS : 0.0);
  const std::string command = EstimatorCommand(ctx, raw_command);
  ctx.host_links = HostLinks(scenario, raw_command, ctx.set);
  AddControllerLinks(ctx);
  ctx.report.estimator_command = opt.emulate_only ? "" : command;
  ctx.fixes_csv.open(ctx.dir + "/gnss_fixes.csv");
  WriteFixCsvHeader(ctx.fixes_csv);
  MakeNavFifo(ctx);
  MakeSharedClock(ctx);
  StartEstimator(ctx, command);
  StartController(ctx);
  if (opt.mode == RunMode::kRealtime && ctx.estimator) AwaitHostLinksOpen(ctx);
  ctx.estimator_start = WallNow();
  if (opt.mode == RunMode::kRealtime) {
    const bool fifo = opt.nice < 0;  // a priority raise asked for: the pacing takes FIFO too
    if (fifo) link::RealtimePacer::RequestRealtimeScheduling();
    link::RealtimePacer clock(opt.speed);  // emulated t = 0 is now
    clock.set_realtime_threads(fifo);
    // a closed loop runs lockstep (the same bytes as in virtual mode), except where frames carry
    // no time and must arrive at their own (CheckCanRunMode)
    const bool lockstep = scenario.closed_loop.enabled && !opt.emulate_only &&
                          !scenario.can.imu_to_estimator && !opt.free_running;
    if (lockstep) {
      ctx.pacer = std::make_unique<LockstepPacer>(clock);
    } else {
      ctx.pacer = std::make_unique<WallClockPacer>(clock);
    }
  }
  ctx.collector.emplace(MakeEstimateReader(scenario.estimator.output, scenario.start_utc),
                        ctx.estimator ? &*ctx.estimator : nullptr, ctx.nav_pty.get(),
                        ctx.dir + "/" + RawEstimateFileName(scenario.estimator.output),
                        &ctx.diagnostics);
  // the raw output kept: at most what a whole run may write (a flood stops the run sooner)
  ctx.collector->set_keep_limit(OutputBudgetBytes(scenario.duration_s));
  EstimatorHealth& health = ctx.health;
  ctx.collector->set_line_observer([&health](const std::string& line) { health.AddLine(line); });
  ctx.collector->set_json_observer(
      {[&health](const nlohmann::json& line) { health.AddJson(line); },
       [&health](const JsonSolutionLine& line) { health.AddScanned(line); }});
}

}  // namespace hil::harness

#include "hil/harness/run/run.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/mcu/mcu_device.h"
#include "hil/harness/dut/estimate_collector.h"
#include "hil/harness/dut/estimator_process.h"
#include "hil/harness/dut/process_group.h"
#include "hil/harness/eval/cross_track.h"
#include "hil/harness/eval/outage_metrics.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/report/report_html.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/run/can_run.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/run/progress.h"
#include "hil/harness/run/run_guard.h"
#include "hil/harness/run/scheduler.h"
#include "hil/harness/run/truth_table.h"
#include "hil/harness/run/virtual_gate.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr double kDrainQuietS = 0.5;  // estimator output quiet this long after the last byte: done
// virtual mode: the most bytes one link may hold unread by the host (the order across links is
// VirtualGate's: before one link's bytes, the others are read to the last byte)
constexpr std::size_t kLinkBacklogBytes = 2048;
// virtual mode's drain: the estimator's whole process group asleep, with nothing left to read,
// in this many consecutive checks this far apart, has finished its output
constexpr int kIdleChecks = 3;
constexpr useconds_t kIdleCheckUs = 1000;
constexpr const char* kNavLink = "ttyNAV";  // pty the estimator writes NMEA into (output nmea_pty)

std::int64_t Now() { return link::RealtimePacer::MonotonicNs(); }
double SecondsSince(std::int64_t t0) { return static_cast<double>(Now() - t0) * 1e-9; }

// The links the estimator reads: those named in its command ({ttyGPS}) or, for navd, in navd.conf.
std::set<std::string> HostLinks(const Scenario& s, const std::string& raw_command,
                                const DeviceSet& set) {
  std::set<std::string> used;
  for (const auto& [name, path] : set.links) {
    if (raw_command.find("{" + name + "}") != std::string::npos) used.insert(name);
  }
  if (raw_command.find("{navd}") != std::string::npos) {
    used.insert(s.gnss.link);
    if (s.estimator.navd_mode == "multi_gnss") {
      for (const auto& rx : s.gnss.receivers) used.insert(rx.link);  // navd reads every receiver
    }
    if (s.mcu.enabled && s.estimator.navd_mode != "gnss_only" && !s.can.imu_to_estimator)
      used.insert(s.mcu.link);
  }
  return used;
}

std::string Secs(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

std::string Seconds(Time t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", ToSeconds(t));
  return b;
}

}  // namespace

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

RunReport RunScenario(const Scenario& scenario, const RunOptions& opt) {
  const std::int64_t wall_start = Now();
  const InterruptGuard
      interrupt_guard;  // Ctrl-C / SIGTERM: stop the estimator, write an incomplete report
  ClearWriteFailures();
  std::error_code ec;
  fs::create_directories(opt.out_dir, ec);
  if (ec || access(opt.out_dir.c_str(), W_OK) != 0) {
    throw std::runtime_error("cannot write the output folder " + opt.out_dir +
                             (ec ? ": " + ec.message() : ""));
  }
  CheckCanRunMode(scenario, opt);
  const std::string dir = fs::absolute(opt.out_dir).string();
  fs::create_directories(dir + "/captures");
  const std::uint64_t seed = opt.seed.value_or(scenario.seed);
  const double silence_s = opt.silence_timeout_s.value_or(scenario.estimator.silence_timeout_s);
  const std::int64_t silence_ns = static_cast<std::int64_t>(silence_s * 1e9);

  RunReport report;
  report.scenario = scenario.name;
  report.scenario_file = scenario.file;
  report.seed = seed;
  report.mode = ModeName(opt.mode, opt.speed);
  report.speed = opt.mode == RunMode::kVirtual ? 1.0 : opt.speed;
  report.sim_time_s = scenario.duration_s;
  report.estimator_output = scenario.estimator.output;
  for (const Fault& f : scenario.faults.faults) {
    report.faults.emplace_back(
        FaultKindName(f.kind),
        Seconds(f.start) + "-" + Seconds(f.end) + " s" + (f.link.empty() ? "" : " on " + f.link));
  }

  FaultRecorder fault_recorder(scenario.faults);

  // ---- devices, links and the estimator under test ----
  DeviceSet set = BuildDevices(scenario, seed, dir);
  WriteNavdConfig(dir + "/navd.conf", scenario, dir + "/" + scenario.gnss.link);
  std::unique_ptr<link::PtyPort> nav_pty;
  std::vector<std::pair<std::string, std::string>> vars{
      {"navd", opt.navd_path}, {"run_dir", dir}, {"seed", std::to_string(seed)}};
  vars.insert(vars.end(), set.links.begin(), set.links.end());
  if (scenario.estimator.output == "nmea_pty" && !opt.emulate_only) {
    nav_pty = std::make_unique<link::PtyPort>(dir + "/" + kNavLink, 115200);
    vars.emplace_back(kNavLink, dir + "/" + kNavLink);
  }
  const std::string raw_command = opt.estimator_command.value_or(scenario.estimator.command);
  const std::string command = Substitute(raw_command, vars);
  const std::set<std::string> host_links = HostLinks(scenario, raw_command, set);
  report.estimator_command = opt.emulate_only ? "" : command;

  std::ofstream fixes_csv(dir + "/gnss_fixes.csv");
  fixes_csv << "t_s,lat_deg,lon_deg,height_m,vel_n_mps,vel_e_mps,vel_d_mps,num_sv,hdop\n";
  if (opt.emulate_only) {
    for (const auto& [name, path] : set.links) std::printf("%s %s\n", name.c_str(), path.c_str());
    std::fflush(stdout);
  }
  std::optional<EstimatorProcess> estimator;
  if (!opt.emulate_only) {
    estimator.emplace(command, dir + "/estimator.stderr");
    report.estimator_pid = estimator->pid();
    // time for the program to open its devices (gpsd flushes a tty's input when it opens it)
    if (scenario.estimator.startup_s > 0)
      usleep(static_cast<useconds_t>(scenario.estimator.startup_s * 1e6));
  }
  const std::int64_t estimator_start = Now();
  std::optional<link::RealtimePacer> pacer;
  if (opt.mode == RunMode::kRealtime) {
    link::RealtimePacer::RequestRealtimeScheduling();
    pacer.emplace(opt.speed);
  }
  EstimateCollector collector(MakeEstimateReader(scenario.estimator.output, scenario.start_unix_ns),
                              estimator ? &*estimator : nullptr, nav_pty.get(),
                              dir + (nav_pty ? "/estimate.nmea" : "/estimate.jsonl"));
  EstimatorHealth health;
  collector.set_line_observer([&](const std::string& line) { health.AddLine(line); });
  collector.set_json_observer([&](const nlohmann::json& line) { health.AddJson(line); });
  const auto estimator_running = [&] { return estimator && estimator->Running(); };
  // why the run must stop early besides the estimator's own failure: a signal, the run folder
  std::optional<std::string> stop_reason;
  Time t_now{};
  const auto interrupted = [&] {
    if (stop_reason) return true;
    if (const int sig = InterruptGuard::received()) {
      stop_reason = std::string("interrupted by ") +
                    (sig == SIGINT    ? "SIGINT"
                     : sig == SIGTERM ? "SIGTERM"
                                      : "SIGHUP") +
                    " at t = " + Seconds(t_now) + " s of " + Secs(scenario.duration_s) + " s";
    } else if (const auto file = FirstWriteFailure()) {
      stop_reason = "cannot write " + *file +
                    " (disk full, file size limit or folder removed) at t = " + Seconds(t_now) +
                    " s";
    }
    return stop_reason.has_value();
  };
  const auto silent_for_ns = [&] {
    return Now() - std::max(collector.last_output_wall_ns(), estimator_start);
  };

  // ---- the run ----
  ByteFaultInjector byte_faults(scenario.faults, seed, &fault_recorder);
  ProgressLine progress(opt.progress);
  Scheduler scheduler(scenario, set, byte_faults, pacer ? &*pacer : nullptr, fixes_csv);
  scheduler.set_recorder(&fault_recorder);
  if (scenario.estimator.output == "n2k_socketcan") {
    collector.AttachBus([&]() -> const std::vector<CanFrame>& { return scheduler.PollBus(); },
                        scenario.start_unix_ns);
  }
  std::optional<std::string> hang;
  // virtual mode: the host sees its links' bytes in emulated-time order (virtual_gate.h); a wait
  // that sees no byte read for the silence timeout ends the run as a hang or a closed port
  std::optional<VirtualGate> gate;
  if (!pacer && !opt.emulate_only) {
    std::vector<SerialEndpoint*> read_by_host;
    for (const auto& ports : set.endpoints) {
      for (const auto& ep : ports) {
        if (host_links.empty() || host_links.count(ep->link_name()))
          read_by_host.push_back(ep.get());
      }
    }
    const auto on_wait = [&, read_by_host, wait_unread = std::size_t{0},
                          wait_progress_ns = std::int64_t{0}](std::size_t unread,
                                                              bool new_wait) mutable {
      if (new_wait || unread < wait_unread) wait_progress_ns = Now();
      wait_unread = unread;
      collector.Poll();
      if (interrupted() || !estimator_running()) return false;
      if (Now() - wait_progress_ns <= silence_ns) return true;
      if (silent_for_ns() > silence_ns) {
        hang = "it stopped reading its input and is silent (" + std::to_string(unread) +
               " bytes unread for " + Secs(silence_s) + " s)";
        return false;
      }
      // still talking but no longer reading: the port was closed by the peer (or is ignored)
      std::string links;
      for (const SerialEndpoint* ep : read_by_host) {
        if (ep->PendingToHost() > 0) links += " " + ep->link_name();
      }
      stop_reason = "the estimator stopped reading" + links + " at t = " + Seconds(t_now) + " s (" +
                    std::to_string(unread) + " bytes unread for " + Secs(silence_s) +
                    " s): the port was closed by the peer or is no longer read";
      return false;
    };
    gate.emplace(read_by_host, kLinkBacklogBytes, on_wait, estimator->pid());
    scheduler.set_gate(&*gate);
  }
  // the truth for the evaluation, sampled on a thread of its own as the run goes (truth_table.h)
  const Time t_end = TimeFromSeconds(scenario.duration_s),
             t_from = TimeFromSeconds(scenario.evaluate_from_s);
  TruthTableBuilder truth_builder(scenario.truth);
  truth_builder.Ask(TruthCsvTimes(scenario));
  std::size_t estimates_asked = 0, fixes_asked = 0;
  const auto ask_truth = [&] {
    const std::vector<EstimateRecord>& est = collector.records();
    const std::vector<EstimateRecord>& fixes = scheduler.fixes();
    if (est.size() > estimates_asked) {
      truth_builder.Ask(RecordTimes(
          {est.begin() + static_cast<std::ptrdiff_t>(estimates_asked), est.end()}, t_from, t_end));
      estimates_asked = est.size();
    }
    if (fixes.size() > fixes_asked) {
      truth_builder.Ask(RecordTimes(
          {fixes.begin() + static_cast<std::ptrdiff_t>(fixes_asked), fixes.end()}, t_from, t_end));
      fixes_asked = fixes.size();
    }
  };
  std::int64_t running_checked_ns = 0;
  const auto run_step = [&](Time t) {
    t_now = t;
    collector.Poll();
    ask_truth();
    // an estimator's solutions come in time order, about as late as its input: what lies a
    // second behind both will not be asked for any more (a straggler only costs Finish a pass)
    if (!collector.records().empty()) {
      truth_builder.Advance(std::min(collector.records().back().t_validity, t) -
                            std::chrono::seconds(1));
    }
    if (interrupted()) return false;
    progress.Update(ToSeconds(t), scenario.duration_s, collector.records().size());
    if (opt.emulate_only) return true;
    // whether the estimator still runs: a wait4() per event costs more than the event in virtual
    // mode, so at most once per millisecond of wall time
    if (const std::int64_t now = Now(); now - running_checked_ns >= 1'000'000) {
      running_checked_ns = now;
      if (!estimator_running()) return false;
    }
    if (pacer && silent_for_ns() > silence_ns) {
      hang = "no output for " + Secs(silence_s) + " s";
      return false;
    }
    return !hang && !stop_reason;
  };
  try {
    scheduler.Run(run_step);
  } catch (const std::exception& e) {
    stop_reason = std::string("the run failed at t = ") + Seconds(t_now) + " s: " + e.what();
  }
  if (!hang && !interrupted()) scheduler.Flush();
  for (const auto& ports : set.endpoints) {
    for (const auto& ep : ports) ep->FlushCapture();
  }
  interrupted();  // a capture that could not be written stops the run here at the latest

  // ---- drain: the host reads every byte and its output is complete ----
  if (!hang && !stop_reason && estimator_running()) {
    if (gate) {
      gate->WaitAllRead();  // gives up (hang, closed port, interrupt) through its wait step
    } else {
      const auto unread = [&] {  // on the links the estimator reads (none named: all)
        std::size_t n = 0;
        for (const auto& ports : set.endpoints) {
          for (const auto& ep : ports) {
            if (host_links.empty() || host_links.count(ep->link_name())) n += ep->PendingToHost();
          }
        }
        return n;
      };
      std::int64_t last_progress = Now();
      std::size_t pending = unread();
      while (estimator_running() && pending > 0 && Now() - last_progress < silence_ns &&
             !interrupted()) {
        usleep(5000);
        collector.Poll();
        const std::size_t p = unread();
        if (p < pending) last_progress = Now();
        pending = p;
      }
    }
  }
  if (!hang && !stop_reason && estimator_running()) {
    // Output complete: in virtual mode, when every process of the estimator's group has slept
    // through a few checks with all its input read (it waits for input that will not come);
    // otherwise (real time, or /proc cannot tell) when its output has been quiet for kDrainQuietS.
    const std::int64_t drain_start = Now();
    GroupActivity before;
    std::int64_t output_before = -1;
    int idle_checks = 0;
    while (estimator_running() && !interrupted()) {
      collector.Poll();
      const std::int64_t last_output = collector.last_output_wall_ns();
      if (gate && last_output > 0) {
        const GroupActivity now = ReadGroupActivity(estimator->pid());
        const bool idle =
            SleptThroughout(before, now) && last_output == output_before && gate->Unread() == 0;
        idle_checks = idle ? idle_checks + 1 : 0;
        before = now;
        output_before = last_output;
        if (idle_checks >= kIdleChecks) break;
      }
      const std::int64_t quiet_ns = Now() - std::max(last_output, drain_start);
      if (last_output > 0 && quiet_ns > static_cast<std::int64_t>(kDrainQuietS * 1e9)) break;
      if (quiet_ns > silence_ns) {
        if (collector.records().empty()) hang = "no output for " + Secs(silence_s) + " s";
        break;
      }
      usleep(gate ? kIdleCheckUs : 10000);
    }
  }
  progress.Finish();
  const bool crashed = !opt.emulate_only && !hang && !stop_reason && !estimator_running();
  const ExitInfo exit_info = estimator ? estimator->Stop() : ExitInfo{};
  collector.Poll();
  report.estimator_exit = estimator ? exit_info.Describe() : "none (emulator only)";
  if (crashed) {
    report.problems.push_back("the estimator ended before the scenario did: " +
                              exit_info.Describe() + " (see estimator.stderr)");
    report.complete = false;
  }
  if (hang) {
    report.problems.push_back("the estimator hung: " + *hang + "; it was stopped (" +
                              exit_info.Describe() + ")");
    report.complete = false;
  }
  if (stop_reason) {
    report.problems.push_back("the run stopped early: " + *stop_reason +
                              "; the estimator was stopped (" + exit_info.Describe() + ")");
    report.complete = false;
    std::fprintf(stderr, "hil: %s; the estimator was stopped, the report is marked incomplete\n",
                 stop_reason->c_str());
  }
  if (!report.complete && !report.problems.empty())
    report.incomplete_reason = report.problems.front();

  // ---- evaluation ----
  const std::vector<EstimateRecord>& estimates = collector.records();
  if (estimates.empty() && !opt.emulate_only)
    report.problems.push_back("the estimator produced no solution");
  // the point the estimate describes: navd fusing the IMU board reports the board (its body origin
  // is the IMU); a GNSS-only navd reports the antenna
  std::string point = scenario.estimator.reference_point;
  if (point == "auto") {
    const bool navd =
        scenario.estimator.command.find("{navd}") != std::string::npos && !opt.estimator_command;
    const std::string& m = scenario.estimator.navd_mode;
    point = !navd || m == "multi_gnss" ? "body"
            : m == "gnss_only"         ? "antenna"
            : scenario.mcu.enabled     ? "imu"
                                       : "body";
  }
  const Eigen::Vector3d p_BX_B_m = point == "antenna" ? scenario.gnss.model.p_BA_B_m
                                   : point == "imu"   ? scenario.mcu.config.mounting.p_BI_B_m
                                                      : Eigen::Vector3d::Zero();
  ask_truth();
  const TruthTable truth_table = truth_builder.Finish();
  std::vector<ErrorSample> est_err =
      CompareWithTruth(truth_table, estimates, p_BX_B_m, t_from, t_end);
  std::vector<ErrorSample> fix_err =
      CompareWithTruth(truth_table, scheduler.fixes(), scenario.gnss.model.p_BA_B_m, t_from, t_end);
  const PlannedPath path = PlannedPathOf(scenario.truth, scenario.duration_s);
  AddCrossTrack(est_err, path);
  AddCrossTrack(fix_err, path);
  report.metrics = ComputeAccuracy(est_err);
  report.baselines = ComputeAccuracy(fix_err);
  report.timing = ComputeOutputTiming(estimates, t_from, t_end, pacer ? opt.speed : 1.0);
  if (!pacer) {  // arrival times mean nothing in virtual mode
    report.timing.jitter_p50_ms.reset(), report.timing.jitter_p99_ms.reset(),
        report.timing.jitter_max_ms.reset();
  }
  report.output_rate_hz = report.timing.output_rate_hz;
  report.outages = ComputeOutages(est_err, scenario.faults, scenario.reconverged_error_m);
  ReportSeries series;
  if (pacer && !estimates.empty()) {
    for (const auto& e : estimates) {
      series.latency_ms.push_back(
          static_cast<double>(e.wall_rx_ns - pacer->WallNsOf(e.t_validity)) * 1e-6 * opt.speed);
    }
    report.latency =
        LatencyStats{Percentile(series.latency_ms, 50), Percentile(series.latency_ms, 99),
                     Percentile(series.latency_ms, 100)};
  }
  for (const auto& ports : set.endpoints) {
    for (const auto& ep : ports) {
      report.gnss_bytes += ep->uart().bytes_sent();
      report.gnss_messages_dropped += ep->uart().messages_dropped();
    }
  }
  if (set.can) AddCanBusReport(*set.can, collector.bus_frames_per_pgn(), report);
  // MCU resets happen in the MCU model: the k-th scripted reset took place when the model counted k
  std::uint64_t mcu_resets = 0;
  for (const auto& dev : set.devices) {
    if (const auto* m = dynamic_cast<const mcu::McuDevice*>(dev.get()))
      mcu_resets += m->stats().resets;
  }
  for (std::size_t i = 0; i < scenario.faults.faults.size(); ++i) {
    const Fault& f = scenario.faults.faults[i];
    if (f.kind == FaultKind::kMcuReset && mcu_resets > 0) {
      fault_recorder.Note(i, f.start);
      --mcu_resets;
    }
  }
  report.fault_injections = fault_recorder.records();
  ComputeRecoveryTimes(report.fault_injections, est_err, scenario.reconverged_error_m);
  report.estimator_health = health;
  report.criteria =
      EvaluateCriteria(scenario.criteria, RunMetricTable(report), AccuracyTable(report.baselines));
  report.fault_messages_dropped = byte_faults.messages_dropped();
  report.fault_bytes_corrupted = byte_faults.bytes_corrupted();
  report.wall_time_s = SecondsSince(wall_start);
  if (collector.unparsed_lines() > 0) {
    std::fprintf(stderr, "hil: %zu estimator output line(s) were not solutions (kept in %s)\n",
                 collector.unparsed_lines(), nav_pty ? "estimate.nmea" : "estimate.jsonl");
  }

  // ---- the run folder: report.json last, and written even when another file cannot be ----
  const auto attempt = [&](const std::function<void()>& write) {
    try {
      write();
    } catch (const std::exception& e) {
      report.problems.push_back(std::string("the run folder is incomplete: ") + e.what());
      report.complete = false;
      if (report.incomplete_reason.empty()) report.incomplete_reason = report.problems.back();
    }
  };
  attempt([&] { WriteErrorsCsv(est_err, dir + "/estimate.csv"); });
  attempt([&] { WriteErrorsCsv(fix_err, dir + "/gnss_fixes_errors.csv"); });
  attempt([&] {
    WriteTruthCsv(truth_table, scenario, dir + "/truth.csv", series.truth_t_s, series.truth_en_m);
  });
  attempt([&] { WriteScheduleErrors(set, dir + "/schedule_error.json"); });
  if (opt.html) {
    series.estimate_errors = std::move(est_err);
    series.fix_errors = std::move(fix_err);
    attempt([&] { WriteReportHtml(report, series, dir); });
  }
  attempt([&] { WriteJunitXml(report, dir + "/junit.xml"); });
  WriteReportJson(report, dir + "/report.json");
  return report;
}

}  // namespace hil::harness

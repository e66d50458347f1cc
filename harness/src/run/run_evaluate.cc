// Phases 4 and 5 of a run: the evaluation against the truth, and the run folder's files.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <numbers>
#include <utility>

#include "hil/harness/devices/device_kind.h"
#include "hil/harness/eval/cross_track.h"
#include "hil/harness/eval/fault_path_deviation.h"
#include "hil/harness/eval/outage_metrics.h"
#include "hil/harness/eval/pass_to_pass.h"
#include "hil/harness/eval/path_tracking.h"
#include "hil/harness/report/output_file.h"
#include "hil/harness/report/run_outputs.h"
#include "hil/harness/run/can_run.h"
#include "hil/harness/scenario/navd_gnss_source.h"
#include "hil/harness/scenario/path_file_reader.h"

#include "run_phases.h"

namespace hil::harness {
namespace {

// What schedule_error.json reports of the run's links and threads (run_outputs.h).
ScheduleRecord ScheduleRecordOf(const DeviceSet& set) {
  ScheduleRecord r;
  for (const auto& ports : set.endpoints) {
    for (const auto& ep : ports)
      r.serial.push_back({ep->link_name(), &ep->schedule_error_us(), ep->bytes_dropped_unread()});
  }
  if (set.can) r.can = ScheduleRecord::Link{set.can->iface(), &set.can->schedule_error_us(), 0};
  r.threads = set.threads;
  r.cpu_at_start = set.cpu_at_start;
  return r;
}

// Row following is scored this far inside both ridge ends (row_deviation.h): the headland turns
// and the entries into a row are not row following. Our choice (the paper gives none).
constexpr double kRowMargin_m = 1.0;

// A solution dated more than this before the run's start or after its end describes no time of
// the run (its clock or its time stamps are wrong). Our choice: 1 s, far beyond any estimator's
// latency, so that no solution of a working estimator is counted.
constexpr double kOutOfRunMarginS = 1.0;

// Solutions dated outside the run are not scored; they are a problem, not silence (issue 40.5:
// solutions ten years ahead, or at the largest time stamp, left a run "complete" and passing).
// The same for solutions outside the scoring's horizon (run_scoring.h).
void CheckSolutionDates(RunContext& ctx, std::size_t scored) {
  RunReport& report = ctx.report;
  const RunScoring& scoring = *ctx.scoring;
  const std::uint64_t total = scoring.solutions(), outside = scoring.outside_run();
  report.solutions_outside_run = outside;
  if (outside > 0) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "%llu of %llu solutions are dated outside the run (before t = %g s or after t = "
                  "%g s; the first at t = %.6g s): they were not scored",
                  static_cast<unsigned long long>(outside), static_cast<unsigned long long>(total),
                  -kOutOfRunMarginS, ToSeconds(ctx.t_end) + kOutOfRunMarginS,
                  scoring.first_outside_s().value_or(0.0));
    report.problems.emplace_back(text);
  }
  const double horizon_s = ToSeconds(Time{} + RunScoring::kLateHorizon);
  if (scoring.too_late() > 0) {
    report.problems.push_back(
        std::to_string(scoring.too_late()) + " solutions arrived more than " +
        SecondsText(horizon_s) +
        " s of emulated time after their time of validity (or no truth came for them): they "
        "were not scored");
  }
  if (scoring.too_early() > 0) {
    report.problems.push_back(std::to_string(scoring.too_early()) +
                              " solutions were dated more than " + SecondsText(horizon_s) +
                              " s after the run's time when they arrived: they were not scored");
  }
  if (total > 0 && scored == 0) {
    report.problems.push_back("no solution was scored: none of the " + std::to_string(total) +
                              " solutions is dated within the evaluated span (" +
                              SecondsText(ToSeconds(ctx.t_from)) + " to " +
                              SecondsText(ToSeconds(ctx.t_end)) + " s) with a truth to compare");
  }
}

// The point the estimate describes: navd fusing the IMU board reports the board (its body origin
// is the IMU); a GNSS-only navd reports the antenna.
Eigen::Vector3d EstimatedPoint(const Scenario& scenario, const RunOptions& opt) {
  ReferencePoint point = scenario.estimator.reference_point;
  if (point == ReferencePoint::kAuto) {
    const bool navd =
        scenario.estimator.command.find("{navd}") != std::string::npos && !opt.estimator_command;
    const NavdMode m = scenario.estimator.navd_mode;
    point = !navd || m == NavdMode::kMultiGnss ? ReferencePoint::kBody
            : m == NavdMode::kGnssOnly         ? ReferencePoint::kAntenna
            : scenario.mcu.enabled             ? ReferencePoint::kImu
                                               : ReferencePoint::kBody;
  }
  return point == ReferencePoint::kAntenna ? NavdAntennaB(scenario)
         : point == ReferencePoint::kImu   ? scenario.mcu.config.mounting.p_BI_B_m
                                           : Eigen::Vector3d::Zero();
}

void EvaluateTiming(RunContext& ctx) {
  RunReport& report = ctx.report;
  const bool on_wall_clock = ctx.pacer->stepping() != Stepping::kVirtual;
  report.timing = ctx.scoring->timing(ctx.t_from, ctx.t_end);
  if (!on_wall_clock) {  // arrival times mean nothing in virtual mode
    report.timing.jitter_p50_ms.reset(), report.timing.jitter_p99_ms.reset(),
        report.timing.jitter_max_ms.reset();
  }
  report.output_rate_hz = report.timing.output_rate_hz;
  const QuantileSketch& latency = ctx.scoring->latency_ms();
  if (on_wall_clock && ctx.scoring->solutions() > 0) {
    report.latency =
        LatencyStats{latency.Percentile(50), latency.Percentile(99), latency.Percentile(100)};
  }
}

// What the links and devices counted; the k-th scripted MCU reset took place when the devices
// counted k resets.
void CountLinksAndDevices(RunContext& ctx) {
  RunReport& report = ctx.report;
  // real time (not lockstep) has no gate to notice a host that does not read: a link it never
  // took a byte of is that (a few bytes lost while it starts are a UART's with no listener yet)
  const bool free_running = ctx.pacer->stepping() == Stepping::kFreeRunning && ctx.estimator;
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports) {
      report.gnss_bytes += ep->uart().bytes_sent();
      report.gnss_messages_dropped += ep->uart().messages_dropped();
      const std::uint64_t dropped = ep->bytes_dropped_unread();
      if (free_running && ctx.HostReads(*ep) && dropped > 0 && ep->schedule_error_us().count() == 0)
        report.problems.push_back("the estimator never read " + ep->link_name() + " (all " +
                                  std::to_string(dropped) + " bytes sent were dropped unread)");
    }
  }
  if (ctx.set.can) AddCanBusReport(*ctx.set.can, ctx.collector->bus_frames_per_pgn(), report);
  if (ctx.set.rover) report.rtk_rover = MakeRtkRoverReport(*ctx.set.rover);
  std::uint64_t resets = 0;
  for (const auto& dev : ctx.set.devices) resets += dev->statistics().resets;
  const std::vector<Fault>& faults = ctx.scenario.faults.faults;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    if (faults[i].kind == FaultKind::kMcuReset && resets > 0) {
      ctx.fault_recorder.Note(i, faults[i].start);
      --resets;
    }
  }
}

// Which of navd's counters speak for a link: its device kind's link_role ("gnss" for the
// receivers', "imu" for the MCU's); any other link is its own role (no counters: only the run's
// drops are judged).
std::string LinkRole(const Scenario& s, const std::string& link) {
  const DeviceKind* kind = DeviceKindOfLink(s, link);
  return kind && !kind->link_role.empty() ? std::string(kind->link_role) : link;
}

// What the estimator says it received against what the run sent (link_integrity.h): each link it
// reads that lost bytes is a problem. Free-running real time starts from the counters of the
// estimator's first solution (it may have opened a port mid-message).
void CheckLinks(RunContext& ctx) {
  if (ctx.options.emulate_only) return;
  RunReport& report = ctx.report;
  std::vector<LinkSent> sent;
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports) {
      if (!ctx.HostReads(*ep)) continue;
      sent.push_back({ep->link_name(), LinkRole(ctx.scenario, ep->link_name()), ep->bytes_sent(),
                      ep->bytes_dropped_attached()});
    }
  }
  const bool free_running = ctx.pacer->stepping() == Stepping::kFreeRunning;
  report.link_integrity = CheckLinkIntegrity(
      sent, ctx.health, free_running ? ctx.health.first_counters : std::map<std::string, double>{},
      ctx.scenario.faults);
  for (const LinkIntegrity& r : report.link_integrity) {
    if (!r.intact) report.problems.push_back(r.problem);
  }
}

void EvaluateFaultsAndCriteria(RunContext& ctx) {
  RunReport& report = ctx.report;
  report.fault_injections = ctx.fault_recorder.records();
  ctx.scoring->ApplyRecoveryTimes(report.fault_injections);
  report.estimator_health = ctx.health;
  CheckLinks(ctx);
  report.realtime_threads = ctx.set.threads;
  std::vector<Criterion> criteria = ctx.scenario.criteria;
  if (!ctx.options.emulate_only) {
    const std::vector<Criterion> defaults =
        DefaultCriteriaFor(ctx.scenario, report, report.default_criteria);
    criteria.insert(criteria.end(), defaults.begin(), defaults.end());
  }
  report.criteria =
      EvaluateCriteria(criteria, RunMetricTable(report), AccuracyTable(report.baselines));
  report.fault_messages_dropped = ctx.byte_faults->messages_dropped();
  report.estimator_other_records = ctx.collector->other_records();
  report.fault_bytes_corrupted = ctx.byte_faults->bytes_corrupted();
  report.wall_time_s = ToSeconds(WallNow() - ctx.wall_start);
  const std::uint64_t dropped = ctx.estimator ? ctx.estimator->dropped_bytes() : 0;
  if (dropped > 0 || ctx.collector->lines_not_kept() > 0) {
    report.problems.push_back(
        "the estimator's output was not all kept: " + std::to_string(dropped) +
        " bytes dropped unread by the run, " + std::to_string(ctx.collector->lines_not_kept()) +
        " lines not written to " + RawEstimateFileName(ctx.scenario.estimator.output) +
        " (it keeps " + std::to_string(ctx.collector->bytes_kept()) + " bytes)");
  }
  if (ctx.estimator && ctx.estimator->overlong_lines() > 0) {
    std::fprintf(stderr, "hil: %llu estimator output line(s) longer than %zu bytes were cut\n",
                 static_cast<unsigned long long>(ctx.estimator->overlong_lines()),
                 EstimatorProcess::kMaxLineBytes);
  }
  if (ctx.collector->unparsed_lines() > 0) {
    std::fprintf(
        stderr,
        "hil: %zu estimator output line(s) were not solutions (kept in %s); the first, "
        "line %zu: %s\n",
        ctx.collector->unparsed_lines(), RawEstimateFileName(ctx.scenario.estimator.output),
        ctx.collector->first_unparsed_line(), ctx.collector->first_unparsed_reason().c_str());
  }
}

// Writes one file of the run folder; a failure marks the report incomplete instead of ending.
void Attempt(RunReport& report, const std::function<void()>& write) {
  try {
    write();
  } catch (const OutputWriteError& e) {
    if (report.write_failure.empty()) report.write_failure = e.what();
    report.problems.push_back(std::string("the run folder is incomplete: ") + e.what());
    report.complete = false;
    if (report.incomplete_reason.empty()) report.incomplete_reason = report.problems.back();
  } catch (const std::exception& e) {
    report.problems.push_back(std::string("the run folder is incomplete: ") + e.what());
    report.complete = false;
    if (report.incomplete_reason.empty()) report.incomplete_reason = report.problems.back();
  }
}

// Passes over the truth vehicle's track at truth.csv's times (10 Hz) from `t_from` to the run's
// end, read from the scoring's file (never held: a run's track may be days long).
TrackPass TruthTrack(const RunContext& ctx, Time t_from) {
  return PassBetween(ctx.scoring->track().Pass(), t_from, ctx.t_end);
}

// Distance along the track from time `from` to its end.
std::optional<double> DistanceAfter(const TrackPass& track, std::optional<Time> from) {
  if (!from) return std::nullopt;
  double d = 0;
  std::optional<TrackSample> last;
  track([&](const TrackSample& s) {
    if (last && last->t >= *from) d += (s.p_N_m - last->p_N_m).norm();
    last = s;
  });
  return d;
}

// Command-link loss: what each window cut (bytes on the serial base, frames on ISOBUS) goes to its
// injection record; the devices count in the order of the scenario's command_link_loss faults.
void NoteLinkLoss(const FaultTimeline& timeline, const std::vector<std::uint64_t>& lost_per_window,
                  FaultRecorder& rec) {
  std::size_t w = 0;
  for (std::size_t i = 0; i < timeline.faults.size() && w < lost_per_window.size(); ++i) {
    if (timeline.faults[i].kind != FaultKind::kCommandLinkLoss) continue;
    if (lost_per_window[w] > 0) rec.Note(i, timeline.faults[i].start, lost_per_window[w]);
    ++w;
  }
}

// Closed loop: what the wheel motors' faults did; each fault's count goes to its injection record.
ClosedLoopFaultsReport ActuatorFaults(const actuator::WheelMotors& motors, FaultRecorder& rec) {
  ClosedLoopFaultsReport r;
  r.saturated_time_s = motors.counters().saturated_s;
  Duration total{}, max{};
  const auto& faults = motors.faults().faults();
  for (std::size_t i = 0; i < faults.size(); ++i) {
    const actuator::WheelMotorFaultCounters& k = motors.faults().counters()[i];
    rec.Note(faults[i].timeline_index, faults[i].start, k.events);
    switch (faults[i].kind) {
      case actuator::WheelMotorFault::Kind::kCommandLatency:
        r.delayed_commands += k.events;
        total += k.added_latency_total;
        max = std::max(max, k.added_latency_max);
        break;
      case actuator::WheelMotorFault::Kind::kSaturation:
        break;
      case actuator::WheelMotorFault::Kind::kStuck:
        r.stuck_time_s += k.held_s;
        r.commands_not_followed += k.events;
        break;
    }
  }
  if (r.delayed_commands > 0) {
    r.added_latency_mean_s = ToSeconds(total) / static_cast<double>(r.delayed_commands);
    r.added_latency_max_s = ToSeconds(max);
  }
  return r;
}

// Closed loop: a command that came after the truth builder had taken (and the scoring scored) a
// later time left those scores on a truth that did not obey it: a problem, never silence.
void NoteStaleTruth(RunContext& ctx) {
  const std::size_t stale = ctx.truth_builder->stale_samples();
  if (stale == 0) return;
  ctx.report.problems.push_back(
      std::to_string(stale) +
      " command(s) came for an instant the truth builder had passed (more than " +
      SecondsText(ToSeconds(Time{} + RunScoring::kLateHorizon)) +
      " s late): what was scored before each was scored on a truth that had not obeyed it");
}

// Closed loop: the truth against the planned path, and what the controller and the base did.
void EvaluateClosedLoop(RunContext& ctx) {
  RunReport& report = ctx.report;
  const PathGeometry geometry = ReadPathGeometry(ctx.scenario.closed_loop.path_file);
  const TrackPass evaluated = TruthTrack(ctx, ctx.t_from);
  report.tracking = ScoreTracking(geometry, evaluated);
  report.pass_to_pass = ScorePassToPass(geometry, evaluated, ctx.scenario.closed_loop.pass_to_pass);
  const TrackPass track = TruthTrack(ctx, Time{});  // the whole run
  report.tracking_faults = ScoreFaultPathDeviations(
      PlannedPath(ReadPathVertices(ctx.scenario.closed_loop.path_file)), track, ctx.scenario.faults,
      DurationFromSeconds(ctx.scenario.closed_loop.fault_window_s));
  ClosedLoopReport c;
  c.controller_command = report.controller_command;
  if (ctx.controller) {
    ctx.controller->Running();
    c.controller_exit = ctx.controller->Describe();
  }
  if (const actuator::BaseSerialDevice* base = ctx.set.base) {
    const auto& k = base->counters();
    const auto& m = base->motors().counters();
    c.control_ticks = k.ticks;
    c.missing_commands = k.missing_commands;
    if (k.first_missing) c.first_missing_s = ToSeconds(*k.first_missing);
    if (k.last_command) c.last_command_s = ToSeconds(*k.last_command);
    c.command_bytes_lost = base->link_loss().total();
    NoteLinkLoss(ctx.scenario.faults, base->link_loss().per_window(), ctx.fault_recorder);
    c.motor_commands = base->session().counters().motor_commands;
    c.invalid_lines = base->session().counters().invalid;
    c.saturated_commands = m.saturated_commands;
    c.watchdog_trips = m.watchdog_trips;
    if (m.watchdog_trips > 0) c.watchdog_trip_s = ToSeconds(m.last_watchdog_trip);
    c.distance_after_last_command_m = DistanceAfter(track, k.last_command);
    if (m.watchdog_trips > 0)
      c.distance_after_watchdog_m = DistanceAfter(track, m.last_watchdog_trip);
    c.faults = ActuatorFaults(base->motors(), ctx.fault_recorder);
  }
  if (const actuator::IsobusSteeringDevice* ecu = ctx.set.steering) {
    const auto& k = ecu->counters();
    const auto& e = ecu->ecu().counters();
    c.control_ticks = k.ticks;
    c.missing_commands = k.missing_commands;
    if (k.first_missing) c.first_missing_s = ToSeconds(*k.first_missing);
    if (k.last_command) c.last_command_s = ToSeconds(*k.last_command);
    c.command_bytes_lost = ecu->link_loss().total();
    NoteLinkLoss(ctx.scenario.faults, ecu->link_loss().per_window(), ctx.fault_recorder);
    c.motor_commands = e.commands_accepted;
    c.invalid_lines = e.wrong_length + e.unknown_source + e.out_of_range;
    c.watchdog_trips = e.watchdog_trips;
    if (e.watchdog_trips > 0) c.watchdog_trip_s = ToSeconds(e.last_watchdog_trip);
    c.distance_after_last_command_m = DistanceAfter(track, k.last_command);
    if (e.watchdog_trips > 0)
      c.distance_after_watchdog_m = DistanceAfter(track, e.last_watchdog_trip);
    c.steering_ecu = MakeSteeringEcuReport(*ecu);
  }
  track([&c](const TrackSample& s) { c.final_speed_mps = s.speed_mps; });  // the last one's
  if (ctx.set.world)  // paper 001: the deviation from the aisles, against the world's ridges
    report.row_following = ScoreRowDeviation(*ctx.set.world, evaluated, kRowMargin_m);
  c.stopped = std::fabs(c.final_speed_mps) < 0.01;
  if (ctx.engine) c.answered_ticks_without_turn = ctx.engine->skipped_control_turns();
  c.stepping = SteppingName(ctx.pacer->stepping());
  if (ctx.pacer->stepping() == Stepping::kLockstep && ctx.engine) {
    const PaceLateness p = ctx.pacer->lateness();
    c.paced_actions = p.actions;
    c.late_actions = p.late;
    c.max_late_ms = static_cast<double>(p.max_late.count()) * 1e-6;
  }
  if (c.control_ticks > 0 && c.motor_commands == 0)  // a controller that never answered
    report.problems.push_back("the controller sent no command in " +
                              std::to_string(c.control_ticks) +
                              " control ticks (see controller.log)");
  report.closed_loop = c;
  NoteStaleTruth(ctx);
}

// Closed loop: the planned path, for the plots (the base's control ticks: RunScoring).
void AddClosedLoopSeries(const RunContext& ctx, ReportSeries& series) {
  series.path_en_m = ReadPathVertices(ctx.scenario.closed_loop.path_file);  // read at load
}

}  // namespace

void StartScoring(RunContext& ctx) {
  const bool on_wall_clock = ctx.pacer->stepping() != Stepping::kVirtual;
  ScoringSetup setup;
  setup.scenario = &ctx.scenario;
  setup.dir = ctx.dir;
  setup.t_from = ctx.t_from;
  setup.t_end = ctx.t_end;
  setup.p_est_B_m = EstimatedPoint(ctx.scenario, ctx.options);
  setup.p_fix_B_m = NavdAntennaB(ctx.scenario);  // the fixes of the receiver navd reads
  setup.faults = ctx.fault_recorder.records();
  setup.speed = on_wall_clock ? ctx.options.speed : 1.0;
  if (const link::RealtimePacer* wall = ctx.pacer->wall_clock(); wall && on_wall_clock)
    setup.wall_time_of = [wall](Time t) { return wall->WallTimeOf(t); };
  setup.expect_solutions = !ctx.options.emulate_only;
  ctx.scoring.emplace(std::move(setup), *ctx.truth_builder);
  if (actuator::BaseSerialDevice* base = ctx.set.base) {
    constexpr double kDeg = 180.0 / std::numbers::pi;
    base->set_tick_tap([&scoring = *ctx.scoring](const actuator::BaseTickRecord& k) {
      scoring.AddControlTick(k.t, k.commanded_yaw_rate_radps * kDeg, k.yaw_rate_radps * kDeg);
    });
  } else if (actuator::IsobusSteeringDevice* steering = ctx.set.steering) {
    constexpr double kDeg = 180.0 / std::numbers::pi;
    steering->set_tick_tap([&scoring = *ctx.scoring](const actuator::SteeringTickRecord& k) {
      scoring.AddSteeringTick(k.t, k.commanded_steer_rad * kDeg, k.steer_rad * kDeg);
    });
  }
}

RunEvaluation Evaluate(RunContext& ctx) {
  const Scenario& scenario = ctx.scenario;
  RunReport& report = ctx.report;
  ctx.AskTruth();
  RunScoring& scoring = *ctx.scoring;
  if (scoring.solutions() == 0 && !ctx.options.emulate_only)
    report.problems.push_back("the estimator produced no solution");
  RunEvaluation ev{scoring.Finish(ctx.t_end), ReportSeries{}};
  report.metrics = scoring.metrics();
  if (!ctx.options.emulate_only) CheckSolutionDates(ctx, report.metrics.samples);
  report.baselines = scoring.baselines();
  EvaluateTiming(ctx);
  report.outages = scoring.outages();
  CountLinksAndDevices(ctx);
  if (scenario.closed_loop.enabled) EvaluateClosedLoop(ctx);
  EvaluateFaultsAndCriteria(ctx);
  return ev;
}

void WriteRunFolder(RunContext& ctx, RunEvaluation& ev) {
  RunReport& report = ctx.report;
  const std::string& dir = ctx.dir;
  RunScoring& scoring = *ctx.scoring;
  // written as the run went; their last lines now
  Attempt(report, [&] { scoring.CommitEstimateCsv(); });
  Attempt(report, [&] { scoring.CommitFixCsv(); });
  Attempt(report, [&] { scoring.CommitTruthCsv(); });
  Attempt(report,
          [&] { WriteScheduleErrors(ScheduleRecordOf(ctx.set), dir + "/schedule_error.json"); });
  if (ctx.options.html) {
    ev.series = scoring.TakeSeries();
    if (ctx.scenario.closed_loop.enabled) AddClosedLoopSeries(ctx, ev.series);
    Attempt(report, [&] { WriteReportHtml(report, ev.series, MakeRunHeader(ctx), dir); });
  }
  Attempt(report, [&] { WriteJunitXml(report, dir + "/junit.xml"); });
  WriteReportJson(report, dir + "/report.json");
}

}  // namespace hil::harness

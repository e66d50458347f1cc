// The sign-off header of report.html (report/run_header.h) from the run's context.
#include <chrono>
#include <filesystem>

#include "hil/harness/core/build_info.h"
#include "hil/harness/core/file_digest.h"
#include "hil/harness/core/machine_load.h"
#include "hil/harness/devices/device_kind.h"
#include "hil/harness/eval/evaluator.h"

#include "run_phases.h"

namespace hil::harness {
namespace {

// The devices the scenario holds, in the device table's order, with their profiles.
std::vector<HeaderDevice> Devices(const Scenario& s) {
  std::vector<HeaderDevice> out;
  for (const DeviceKind* k : DeviceKinds()) {
    const std::vector<std::string> links = k->links(s);
    if (links.empty()) continue;
    HeaderDevice d{std::string(k->name), "", k->profile ? k->profile(s) : ""};
    for (const std::string& l : links) d.links += (d.links.empty() ? "" : ", ") + l;
    out.push_back(d);
  }
  return out;
}

// The schedule error and dropped bytes of each link (real time and scaled; none in virtual mode).
std::vector<HeaderLink> Links(const RunContext& ctx) {
  std::vector<HeaderLink> out;
  if (ctx.pacer && ctx.pacer->stepping() == Stepping::kVirtual) return out;
  const auto add = [&out](const std::string& name, const QuantileSketch& e, const char* unit,
                          std::uint64_t dropped) {
    if (e.count() == 0 && dropped == 0) return;
    HeaderLink l{name, e.count(), unit, std::nullopt, std::nullopt, std::nullopt, dropped};
    if (e.count() > 0)
      l.p50_us = e.Percentile(50), l.p99_us = e.Percentile(99), l.max_us = e.Percentile(100);
    out.push_back(l);
  };
  for (const auto& ports : ctx.set.endpoints) {
    for (const auto& ep : ports)
      add(ep->link_name(), ep->schedule_error_us(), "bytes", ep->bytes_dropped_unread());
  }
  if (ctx.set.can) add(ctx.set.can->iface(), ctx.set.can->schedule_error_us(), "frames", 0);
  return out;
}

// Which build of the estimator ran: this build's navd when the command names {navd}.
std::string EstimatorBuild(const RunContext& ctx) {
  const std::string& raw = ctx.options.estimator_command ? *ctx.options.estimator_command
                                                         : ctx.scenario.estimator.command;
  if (raw.find("{navd}") == std::string::npos)
    return "an external estimator: hil does not know its version";
  return "navd " + std::string(HilVersion()) + " from the same build as hil (" +
         ctx.options.navd_path + ", commit " + std::string(HilCommit()) + ")";
}

}  // namespace

RunHeader MakeRunHeader(const RunContext& ctx) {
  const Scenario& s = ctx.scenario;
  RunHeader h;
  if (std::filesystem::is_regular_file(s.file))
    h.scenario_sha256 = Sha256OfFile(s.file).value_or("");
  h.short_form = s.short_form;
  h.origin_lat_deg = s.truth.origin.lat_deg;
  h.origin_lon_deg = s.truth.origin.lon_deg;
  h.origin_height_m = s.truth.origin.height_m;
  h.scenario_start_utc = UtcText(s.start_utc);
  // the run's start: UTC now less the wall time the run has taken
  h.run_started_utc = UtcText(UnixClock::now() - (WallNow() - ctx.wall_start));
  h.devices = Devices(s);
  h.hil_version = HilVersion();
  h.hil_commit = HilCommit();
  h.estimator_build = EstimatorBuild(ctx);
  if (s.closed_loop.enabled)
    h.controller = ctx.report.closed_loop ? ctx.report.closed_loop->controller_command
                                          : s.closed_loop.controller;
  h.cpu_model = ReadCpuModel();
  const MachineFigures m = ReadMachineFigures();
  h.kernel = m.kernel;
  h.cpus_online = m.cpus_online;
  h.stepping = ctx.pacer ? SteppingName(ctx.pacer->stepping()) : "virtual";
  h.links = Links(ctx);
  return h;
}

}  // namespace hil::harness

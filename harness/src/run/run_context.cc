#include "hil/harness/run/run_context.h"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include "hil/harness/engine/virtual_pacer.h"
#include "hil/harness/run/run_guard.h"

namespace hil::harness {

OwnedFd::~OwnedFd() {
  if (fd >= 0) close(fd);
}

std::uint64_t OutputBudgetBytes(double t_s) {
  return kOutputBaseBytes + static_cast<std::uint64_t>(
                                std::max(0.0, t_s) * static_cast<double>(kOutputBytesPerEmulatedS));
}

std::string SecondsText(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

std::string SecondsText(Time t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", ToSeconds(t));
  return b;
}

RunContext::RunContext(const Scenario& s, const RunOptions& o)
    : scenario(s),
      options(o),
      wall_start(WallNow()),
      dir(std::filesystem::absolute(o.out_dir).string()),
      seed(o.seed.value_or(s.seed)),
      silence_s(o.silence_timeout_s.value_or(s.estimator.silence_timeout_s)),
      silence(static_cast<std::int64_t>(silence_s * 1e9)),
      t_end(TimeFromSeconds(s.duration_s)),
      t_from(TimeFromSeconds(s.evaluate_from_s)),
      fault_recorder(s.faults),
      pacer(std::make_unique<VirtualPacer>()) {}

bool RunContext::Interrupted() {
  if (stop_reason) return true;
  if (const int sig = InterruptGuard::received()) {
    report.interrupt_signal = sig;
    stop_reason = std::string("interrupted by ") +
                  (sig == SIGINT    ? "SIGINT"
                   : sig == SIGTERM ? "SIGTERM"
                                    : "SIGHUP") +
                  " at t = " + SecondsText(t_now) + " s of " + SecondsText(scenario.duration_s) +
                  " s";
  } else if (collector && collector->output_bytes() > OutputBudgetBytes(ToSeconds(t_now))) {
    stop_reason = "the estimator floods its output: " + std::to_string(collector->output_bytes()) +
                  " bytes by t = " + SecondsText(t_now) + " s, more than the " +
                  std::to_string(OutputBudgetBytes(ToSeconds(t_now))) + " allowed by then (" +
                  std::to_string(kOutputBaseBytes) + " + " +
                  std::to_string(kOutputBytesPerEmulatedS) +
                  " per emulated second); the rest of its output was not kept";
    collector->set_keep_limit(collector->bytes_kept());
  } else if (const auto file = diagnostics.FirstWriteFailure()) {
    report.write_failure = "cannot write " + *file;
    stop_reason = "cannot write " + *file +
                  " (disk full, file size limit or folder removed) at t = " + SecondsText(t_now) +
                  " s";
  }
  return stop_reason.has_value();
}

Duration RunContext::SilentFor() const {
  return WallNow() - std::max(collector->last_output_wall(), estimator_start);
}

bool RunContext::HostReads(const SerialEndpoint& ep) const {
  const std::string& name = ep.link_name();
  if (controller_gone && controller_links.count(name)) return false;
  return host_links.empty() || host_links.count(name) > 0;
}

void RunContext::ControllerGone() {
  if (controller_gone) return;
  controller_gone = true;
  if (!gate) return;
  for (const auto& ports : set.endpoints) {
    for (const auto& ep : ports) {
      if (controller_links.count(ep->link_name())) gate->StopReading(*ep);
    }
  }
}

void RunContext::AskTruth() {
  collector->TakeRecords(taken_estimates);
  scoring->AddEstimates(taken_estimates, t_now);
  baseline->TakeFixes(taken_fixes);
  scoring->AddFixes(taken_fixes);
  scoring->Advance(t_now);
}

}  // namespace hil::harness

#include "hil/harness/run/progress.h"

#include <cstdio>

#include "hil/firmware_emu/link/realtime_pacer.h"

namespace hil::harness {

namespace {
constexpr std::int64_t kRedrawNs = 200'000'000;
}

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled), wall_start_ns_(link::RealtimePacer::MonotonicNs()) {}

ProgressLine::~ProgressLine() { Finish(); }

void ProgressLine::Update(double sim_s, double total_s, std::size_t solutions) {
  if (!enabled_) return;
  const std::int64_t now = link::RealtimePacer::MonotonicNs();
  if (drawn_ && now - last_draw_ns_ < kRedrawNs) return;
  last_draw_ns_ = now;
  drawn_ = true;
  const double wall_s = static_cast<double>(now - wall_start_ns_) * 1e-9;
  const double pct = total_s > 0 ? 100.0 * sim_s / total_s : 0.0;
  std::fprintf(stderr, "\r\033[K[%6.1f/%.1f s %3.0f%%] %6.1fx real time  %zu solutions", sim_s,
               total_s, pct, wall_s > 0 ? sim_s / wall_s : 0.0, solutions);
  std::fflush(stderr);
}

void ProgressLine::Finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace hil::harness

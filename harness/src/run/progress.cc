#include "hil/harness/run/progress.h"

#include <cstdio>

#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {

namespace {
constexpr Duration kRedraw = std::chrono::milliseconds(200);
}

ProgressLine::ProgressLine(bool enabled) : enabled_(enabled), wall_start_(WallNow()) {}

ProgressLine::~ProgressLine() { Finish(); }

void ProgressLine::Update(double sim_s, double total_s, std::size_t solutions) {
  if (!enabled_) return;
  const WallTime now = WallNow();
  if (drawn_ && now - last_draw_ < kRedraw) return;
  last_draw_ = now;
  drawn_ = true;
  const double wall_s = ToSeconds(now - wall_start_);
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

#pragma once
/// @file
/// A live one-line progress display on a terminal (stderr), redrawn at most 5 times a second:
///   [ 42.0/120.0 s  35%]  1.8x real time  87 solutions
/// Disabled (prints nothing) when stderr is not a terminal.

#include <string>

#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {

class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  /// Redraws if enough wall time has passed since the last redraw.
  void Update(double sim_s, double total_s, std::size_t solutions);
  /// Clears the line (also done by the destructor).
  void Finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  WallTime wall_start_, last_draw_{};
};

}  // namespace hil::harness

#pragma once
/// @file
/// A live one-line progress display on a terminal (stderr), redrawn at most 5 times a second:
///   [ 42.0/120.0 s  35%]  1.8x real time  87 solutions
/// Disabled (prints nothing) when stderr is not a terminal.

#include <cstdint>
#include <string>

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
  std::int64_t wall_start_ns_ = 0, last_draw_ns_ = 0;
};

}  // namespace hil::harness

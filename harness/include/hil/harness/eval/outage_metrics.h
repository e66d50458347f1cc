#pragma once
/// @file
/// Behaviour of the estimate around each scripted GNSS outage of the fault timeline, and the
/// timing of its output stream.

#include <optional>
#include <vector>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/scenario/fault_timeline.h"

namespace hil::harness {

struct OutageMetrics {
  double start_s = 0, end_s = 0;
  std::size_t samples = 0;            ///< solutions inside the outage
  double max_horizontal_error_m = 0;  ///< over solutions valid in [start, end]
  /// Largest |error| along each local axis (east, north, up) over the same solutions (paper 004
  /// states its outage result per axis).
  Eigen::Vector3d max_abs_error_enu_m = Eigen::Vector3d::Zero();
  /// Horizontal error against time since the outage start: (horizon s, error m) at 1, 2, 5, 10,
  /// 20, 30, 60 s where the outage lasts that long (the latest solution at or before the horizon).
  std::vector<std::pair<double, double>> growth;
  /// Seconds after the end until the error is below the threshold and stays there for 2 s (or
  /// until the next outage); absent when it never does.
  std::optional<double> reconvergence_time_s;
};

/// One entry per gnss_outage fault, in time order.
std::vector<OutageMetrics> ComputeOutages(const std::vector<ErrorSample>& errors,
                                          const FaultTimeline& faults, double reconverged_error_m);

/// Rate and regularity of the output stream over the evaluated window.
struct OutputTiming {
  double output_rate_hz = 0;  ///< solutions valid in the window per second of the window
  /// Solutions missing from the window as a fraction of those expected: gaps between solutions
  /// longer than 1.5 nominal periods (the median interval), and the gaps between the window's
  /// start or end and the first or last solution (a stream that stops early or starts late misses
  /// solutions too). 1 when the window holds no solution.
  double missing_fraction = 0;
  std::optional<double> jitter_p50_ms, jitter_p99_ms,
      jitter_max_ms;  ///< |arrival interval − median|, wall clock
};

/// Timing of the records valid in [t_from, t_to] (the evaluated window), sorted or not; arrival
/// jitter only when records carry wall times. `speed` scales wall intervals to emulated time.
OutputTiming ComputeOutputTiming(const std::vector<EstimateRecord>& records, Time t_from, Time t_to,
                                 double speed);

}  // namespace hil::harness

#pragma once
/// @file
/// Closed loop: what each fault of the scenario did to the path tracking (report.json
/// `tracking.faults`). For a fault on [start, end): the truth's signed cross-track at its start,
/// and its largest departure from that value from the start to `window` after the end (the fault
/// and the controller's recovery), with the time it happened. An estimator glitch that the
/// controller follows shows up here as the vehicle's deviation from its path.

#include <optional>
#include <string>
#include <vector>

#include "hil/harness/eval/cross_track.h"
#include "hil/harness/eval/path_tracking.h"
#include "hil/harness/scenario/fault_timeline.h"

namespace hil::harness {

struct FaultPathDeviation {
  std::string kind;
  double start_s = 0, end_s = 0;
  double window_s = 0;  ///< scored from start_s to end_s + window_s
  std::size_t samples = 0;
  std::optional<double> cross_track_at_start_m;
  /// The largest |XTE − XTE at start| in the window, its time and the XTE then.
  std::optional<double> max_deviation_m, max_deviation_s, cross_track_at_max_m;
  std::optional<double> max_abs_cross_track_m;  ///< the largest |XTE| in the window
};

/// One entry per fault of `faults`, in file order. `track` is the truth's (time order).
std::vector<FaultPathDeviation> ScoreFaultPathDeviations(const PlannedPath& path,
                                                         const TrackPass& track,
                                                         const FaultTimeline& faults,
                                                         Duration window);

}  // namespace hil::harness

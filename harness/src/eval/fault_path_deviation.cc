#include "hil/harness/eval/fault_path_deviation.h"

#include <cmath>

namespace hil::harness {

std::vector<FaultPathDeviation> ScoreFaultPathDeviations(const PlannedPath& path,
                                                         const TrackPass& track,
                                                         const FaultTimeline& faults,
                                                         Duration window) {
  std::vector<FaultPathDeviation> out;
  for (const Fault& f : faults.faults) {
    FaultPathDeviation d;
    d.kind = FaultKindName(f.kind);
    d.start_s = ToSeconds(f.start);
    d.end_s = ToSeconds(f.end);
    d.window_s = ToSeconds(window);
    const Time until = f.end + window;
    track([&](const TrackSample& s) {
      if (s.t < f.start || s.t > until) return;
      const double xte = path.CrossTrack(s.p_N_m);
      ++d.samples;
      if (!d.cross_track_at_start_m) d.cross_track_at_start_m = xte;
      const double dev = std::fabs(xte - *d.cross_track_at_start_m);
      if (!d.max_deviation_m || dev > *d.max_deviation_m) {
        d.max_deviation_m = dev;
        d.max_deviation_s = ToSeconds(s.t);
        d.cross_track_at_max_m = xte;
      }
      if (!d.max_abs_cross_track_m || std::fabs(xte) > *d.max_abs_cross_track_m)
        d.max_abs_cross_track_m = std::fabs(xte);
    });
    out.push_back(d);
  }
  return out;
}

}  // namespace hil::harness

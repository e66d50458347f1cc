#include "hil/harness/eval/spilled_track.h"

namespace hil::harness {

void SpilledTrack::Add(const TrackSample& s) {
  file_.Add(Record{(s.t - Time{}).count(), s.p_N_m.x(), s.p_N_m.y(), s.yaw_rad, s.speed_mps});
  if (!front_) front_ = s;
  back_ = s;
}

TrackPass SpilledTrack::Pass() const {
  return [this](const TrackVisit& visit) {
    file_.ForEach([&](const Record& r) {
      TrackSample s;
      s.t = Time{} + Duration(r.t_ns);
      s.p_N_m = {r.east_m, r.north_m};
      s.yaw_rad = r.yaw_rad;
      s.speed_mps = r.speed_mps;
      visit(s);
    });
  };
}

}  // namespace hil::harness

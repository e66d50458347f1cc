#include "hil/harness/eval/row_deviation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hil::harness {

RowDeviation ScoreRowDeviation(const world::GreenhouseWorld& world, const TrackPass& track,
                               double margin_m) {
  RowDeviation r;
  const double length = world.config().ridge_length_m;
  const Eigen::Vector2d& u = world.row_axis();
  const double row_yaw = std::atan2(u.y(), u.x());
  double sum_abs = 0;
  track([&](const TrackSample& s) {
    const world::AislePosition a = world.Locate(s.p_N_m);
    if (!a.between_ridges || a.along_m < margin_m || a.along_m > length - margin_m) return;
    double dyaw = std::remainder(s.yaw_rad - row_yaw, std::numbers::pi);  // either way along
    dyaw = std::abs(dyaw) * 180.0 / std::numbers::pi;
    r.max_lateral_deviation_m = std::max(r.max_lateral_deviation_m, std::abs(a.lateral_m));
    r.max_heading_deviation_deg = std::max(r.max_heading_deviation_deg, dyaw);
    sum_abs += std::abs(a.lateral_m);
    ++r.samples;
  });
  if (r.samples > 0) r.mean_abs_lateral_m = sum_abs / static_cast<double>(r.samples);
  return r;
}

}  // namespace hil::harness

#include "hil/firmware_emu/world/sky_obstructions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hil::world {
namespace {

constexpr double kTiny = 1e-9;

// Slant length of the direct path inside obstacle `o` (0 when it does not cross it).
double SlantInside(const SkyObstacle& o, const Eigen::Vector3d& p_NA_N_m, double az_rad,
                   double el_rad) {
  const double ce = std::cos(el_rad), se = std::sin(el_rad);
  const Ray2 ray{p_NA_N_m.head<2>(), Eigen::Vector2d(std::sin(az_rad), std::cos(az_rad))};
  const auto span = CrossBox(ray, o.footprint);
  if (!span) return 0.0;
  double s_enter = 0.0, s_exit = std::numeric_limits<double>::infinity();
  if (ce > kTiny) {
    s_enter = std::max(span->enter_m, 0.0) / ce;
    s_exit = span->exit_m / ce;
  } else if (span->enter_m > 0.0) {
    return 0.0;  // looking straight up from outside the footprint
  }
  const double above_m = o.height_m - p_NA_N_m.z();
  if (above_m <= 0.0) return 0.0;  // the antenna is above the obstacle's top
  const double s_top = se > kTiny ? above_m / se : std::numeric_limits<double>::infinity();
  const double s_end = std::min(s_exit, s_top);
  return s_end > s_enter ? s_end - s_enter : 0.0;
}

// The reflection off one vertical face (outward normal n2, centre f, half length along it).
std::optional<Reflection> FaceReflection(const SkyObstacle& o, const Eigen::Vector2d& n2,
                                         const Eigen::Vector2d& f, const Eigen::Vector2d& t2,
                                         double half_along_m, const Eigen::Vector3d& p_A,
                                         const Eigen::Vector3d& s) {
  const double d = n2.dot(p_A.head<2>() - f);
  const double sn = s.head<2>().dot(n2);
  if (d <= 0.0 || sn <= kTiny) return std::nullopt;  // antenna or satellite behind the face
  const double len = d / sn;                         // antenna → reflection point
  const Eigen::Vector2d s_ref_h = s.head<2>() - 2.0 * sn * n2;
  const Eigen::Vector2d r_h = p_A.head<2>() + len * s_ref_h;
  const double r_z = p_A.z() + len * s.z();
  if (std::abs(t2.dot(r_h - f)) > half_along_m || r_z < 0.0 || r_z > o.height_m)
    return std::nullopt;
  return Reflection{2.0 * d * sn, o.reflection_amplitude, 0};
}

}  // namespace

std::optional<SkyObstacleProblem> CheckSkyObstacle(const SkyObstacle& o) {
  auto bad = [](const char* f, const char* m) { return SkyObstacleProblem{f, m}; };
  if (!(o.height_m > 0)) return bad("height_m", "must be positive");
  if (!(o.footprint.half_extent_m.x() > 0) || !(o.footprint.half_extent_m.y() > 0))
    return bad("size", "the footprint must have a positive length and width");
  if (!(o.loss_db >= 0)) return bad("loss_db", "must not be negative");
  if (!(o.loss_db_per_m >= 0)) return bad("loss_db_per_m", "must not be negative");
  if (!(o.max_loss_db >= 0)) return bad("max_loss_db", "must not be negative");
  if (!(o.reflection_amplitude >= 0 && o.reflection_amplitude <= 1))
    return bad("reflection_amplitude", "must be within 0 … 1");
  return std::nullopt;
}

SkyObstructions::SkyObstructions(std::vector<SkyObstacle> obstacles)
    : obstacles_(std::move(obstacles)) {
  for (const SkyObstacle& o : obstacles_) {
    if (auto p = CheckSkyObstacle(o)) throw std::invalid_argument(p->field + ": " + p->message);
  }
}

LineOfSight SkyObstructions::Trace(const Eigen::Vector3d& p_NA_N_m, double az_rad,
                                   double el_rad) const {
  LineOfSight los;
  for (const SkyObstacle& o : obstacles_) {
    const double inside_m = SlantInside(o, p_NA_N_m, az_rad, el_rad);
    if (inside_m <= 0.0) continue;
    ++los.crossed;
    if (o.opaque) {
      los.blocked = true;
      continue;
    }
    los.loss_db += std::min(o.max_loss_db, o.loss_db + o.loss_db_per_m * inside_m);
  }
  return los;
}

std::optional<Reflection> SkyObstructions::StrongestReflection(const Eigen::Vector3d& p_NA_N_m,
                                                               double az_rad, double el_rad) const {
  const Eigen::Vector3d s(std::cos(el_rad) * std::sin(az_rad), std::cos(el_rad) * std::cos(az_rad),
                          std::sin(el_rad));
  std::optional<Reflection> best;
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    const SkyObstacle& o = obstacles_[i];
    if (o.reflection_amplitude <= 0.0) continue;
    const OrientedBox& b = o.footprint;
    const Eigen::Vector2d ax0(std::cos(b.heading_rad), std::sin(b.heading_rad));
    const Eigen::Vector2d ax1(-ax0.y(), ax0.x());
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector2d& axis = k == 0 ? ax0 : ax1;
      const Eigen::Vector2d& along = k == 0 ? ax1 : ax0;
      for (const double sign : {-1.0, 1.0}) {
        const Eigen::Vector2d n2 = sign * axis;
        const Eigen::Vector2d f = b.centre_m + sign * b.half_extent_m[k] * axis;
        auto r = FaceReflection(o, n2, f, along, b.half_extent_m[1 - k], p_NA_N_m, s);
        if (!r) continue;
        r->obstacle = static_cast<int>(i);
        if (!best || r->amplitude > best->amplitude ||
            (r->amplitude == best->amplitude && r->excess_path_m < best->excess_path_m))
          best = r;
      }
    }
  }
  return best;
}

}  // namespace hil::world

#include "hil/firmware_emu/world/ray_cast.h"

#include <cmath>
#include <limits>

namespace hil::world {

bool MayHitCircle(const Ray2& ray, const Eigen::Vector2d& centre_m, double radius_m,
                  double max_range_m) {
  const Eigen::Vector2d d = centre_m - ray.origin_m;
  const double along = d.dot(ray.dir);
  if (along < -radius_m || along > max_range_m + radius_m) return false;
  const double across = ray.dir.x() * d.y() - ray.dir.y() * d.x();
  return std::abs(across) <= radius_m;
}

std::optional<RayHit> CastBox(const Ray2& ray, const OrientedBox& box, double max_range_m) {
  // In the box frame: rotate by −heading about the centre, then the slab method on both axes.
  const double c = std::cos(box.heading_rad), s = std::sin(box.heading_rad);
  const Eigen::Vector2d d = ray.origin_m - box.centre_m;
  const Eigen::Vector2d o(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const Eigen::Vector2d u(c * ray.dir.x() + s * ray.dir.y(), -s * ray.dir.x() + c * ray.dir.y());
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int enter_axis = -1;
  double enter_sign = 0;
  for (int k = 0; k < 2; ++k) {
    const double h = box.half_extent_m[k];
    if (u[k] == 0.0) {
      if (std::abs(o[k]) > h) return std::nullopt;
      continue;
    }
    double t0 = (-h - o[k]) / u[k], t1 = (h - o[k]) / u[k];
    double sign = -1;  // entering through the −h face when moving in +k
    if (t0 > t1) std::swap(t0, t1), sign = 1;
    if (t0 > t_enter) t_enter = t0, enter_axis = k, enter_sign = sign;
    t_exit = std::min(t_exit, t1);
  }
  if (t_enter > t_exit || t_exit < 0) return std::nullopt;
  RayHit hit;
  if (t_enter < 0) {  // the origin is inside the box
    hit.normal = -ray.dir;
    return hit;
  }
  if (t_enter > max_range_m) return std::nullopt;
  hit.range_m = t_enter;
  const Eigen::Vector2d n_box =
      enter_axis == 0 ? Eigen::Vector2d(enter_sign, 0) : Eigen::Vector2d(0, enter_sign);
  hit.normal = Eigen::Vector2d(c * n_box.x() - s * n_box.y(), s * n_box.x() + c * n_box.y());
  return hit;
}

std::optional<RayHit> CastSegment(const Ray2& ray, const Eigen::Vector2d& a_m,
                                  const Eigen::Vector2d& b_m, double max_range_m) {
  // origin + t·dir = a + w·(b − a), t ≥ 0, w ∈ [0, 1]
  const Eigen::Vector2d e = b_m - a_m;
  const double den = ray.dir.x() * e.y() - ray.dir.y() * e.x();
  if (std::abs(den) < 1e-15) return std::nullopt;
  const Eigen::Vector2d q = a_m - ray.origin_m;
  const double t = (q.x() * e.y() - q.y() * e.x()) / den;
  const double w = (q.x() * ray.dir.y() - q.y() * ray.dir.x()) / den;
  if (t < 0 || t > max_range_m || w < 0 || w > 1) return std::nullopt;
  Eigen::Vector2d n(-e.y(), e.x());
  n.normalize();
  if (n.dot(ray.dir) > 0) n = -n;
  return RayHit{t, n};
}

std::optional<RaySpan> CrossBox(const Ray2& ray, const OrientedBox& box) {
  const double c = std::cos(box.heading_rad), s = std::sin(box.heading_rad);
  const Eigen::Vector2d d = ray.origin_m - box.centre_m;
  const Eigen::Vector2d o(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  const Eigen::Vector2d u(c * ray.dir.x() + s * ray.dir.y(), -s * ray.dir.x() + c * ray.dir.y());
  RaySpan span{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (int k = 0; k < 2; ++k) {
    const double h = box.half_extent_m[k];
    if (u[k] == 0.0) {
      if (std::abs(o[k]) > h) return std::nullopt;
      continue;
    }
    const double t0 = (-h - o[k]) / u[k], t1 = (h - o[k]) / u[k];
    span.enter_m = std::max(span.enter_m, std::min(t0, t1));
    span.exit_m = std::min(span.exit_m, std::max(t0, t1));
  }
  if (span.enter_m > span.exit_m || span.exit_m < 0) return std::nullopt;
  return span;
}

}  // namespace hil::world

#include "hil/firmware_emu/world/greenhouse_world.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::world {
namespace {

std::optional<ConfigProblem> CheckSizes(const GreenhouseConfig& c) {
  auto bad = [](const char* f, const char* m) { return ConfigProblem{f, m}; };
  if (c.ridge_count < 1) return bad("ridge_count", "needs at least one ridge");
  if (!(c.ridge_width_m > 0)) return bad("ridge_width_m", "must be positive");
  if (!(c.ridge_height_m > 0)) return bad("ridge_height_m", "must be positive");
  if (!(c.ridge_length_m > 0)) return bad("ridge_length_m", "must be positive");
  if (c.ridge_count > 1 && !(c.ridge_spacing_m > c.ridge_width_m))
    return bad("ridge_spacing_m", "must exceed ridge_width_m: the ridges would overlap (no aisle)");
  if (!(c.headland_m >= 0)) return bad("headland_m", "must not be negative");
  if (!(c.side_margin_m >= 0)) return bad("side_margin_m", "must not be negative");
  if (!(c.wall_height_m > 0)) return bad("wall_height_m", "must be positive");
  return std::nullopt;
}

}  // namespace

std::optional<ConfigProblem> CheckGreenhouse(const GreenhouseConfig& c) {
  if (auto p = CheckSizes(c)) return p;
  if (!(c.post_spacing_m >= 0)) return ConfigProblem{"post_spacing_m", "must not be negative"};
  if (c.post_spacing_m > 0) {
    if (!(c.post_size_m > 0)) return ConfigProblem{"post_size_m", "must be positive"};
    if (c.post_size_m >= c.post_spacing_m)
      return ConfigProblem{"post_size_m", "must be smaller than post_spacing_m"};
    if (c.post_size_m > c.side_margin_m)
      return ConfigProblem{"post_size_m", "posts stand in the side margin: must not exceed it"};
    if (!(c.post_height_m > 0)) return ConfigProblem{"post_height_m", "must be positive"};
  }
  return std::nullopt;
}

GreenhouseWorld::GreenhouseWorld(const GreenhouseConfig& config) : config_(config) {
  if (auto p = CheckGreenhouse(config_)) {
    throw std::invalid_argument("greenhouse: " + p->field + ": " + p->message);
  }
  const double a = config_.row_direction_deg * std::numbers::pi / 180.0;
  u_ = Eigen::Vector2d(std::cos(a), std::sin(a));
  v_ = Eigen::Vector2d(-u_.y(), u_.x());
  Build();
}

Eigen::Vector2d GreenhouseWorld::Map(double along_m, double left_m) const {
  return config_.first_ridge_start_N_m + along_m * u_ + left_m * v_;
}

void GreenhouseWorld::Build() {
  const GreenhouseConfig& c = config_;
  const double heading = std::atan2(u_.y(), u_.x());
  for (int i = 0; i < c.ridge_count; ++i) {
    const Eigen::Vector2d half(c.ridge_length_m / 2, c.ridge_width_m / 2);
    ridges_.push_back({Map(c.ridge_length_m / 2, i * c.ridge_spacing_m), half, heading});
    ridge_radius_m_.push_back(half.norm());
  }
  // The walls' inner faces: ends `headland_m` beyond the ridge ends, sides `side_margin_m`
  // beyond the outer ridges' sides.
  const double s0 = -c.headland_m, s1 = c.ridge_length_m + c.headland_m;
  const double n0 = -c.ridge_width_m / 2 - c.side_margin_m;
  const double n1 = (c.ridge_count - 1) * c.ridge_spacing_m + c.ridge_width_m / 2 + c.side_margin_m;
  const Eigen::Vector2d p00 = Map(s0, n0), p10 = Map(s1, n0), p11 = Map(s1, n1), p01 = Map(s0, n1);
  walls_ = {{p00, p01}, {p00, p10}, {p10, p11}, {p01, p11}};
  if (c.post_spacing_m <= 0) return;
  const double h = c.post_size_m / 2;
  const auto count = static_cast<int>(std::floor((s1 - s0) / c.post_spacing_m + 1e-9));
  for (int k = 0; k <= count; ++k) {
    const double s = std::clamp(s0 + k * c.post_spacing_m, s0 + h, s1 - h);
    for (const double n : {n0 + h, n1 - h}) {
      posts_.push_back({Map(s, n), Eigen::Vector2d(h, h), heading});
      post_radius_m_.push_back(h * std::numbers::sqrt2);
    }
  }
}

std::optional<WorldHit> GreenhouseWorld::Cast(const Ray2& ray, double height_m,
                                              double max_range_m) const {
  std::optional<WorldHit> best;
  double limit = max_range_m;
  auto take = [&](const std::optional<RayHit>& h, ObstacleKind kind, std::size_t i) {
    if (!h || h->range_m > limit) return;
    limit = h->range_m;
    best = WorldHit{h->range_m, kind, static_cast<int>(i), h->normal};
  };
  if (height_m < config_.ridge_height_m) {
    for (std::size_t i = 0; i < ridges_.size(); ++i) {
      if (MayHitCircle(ray, ridges_[i].centre_m, ridge_radius_m_[i], limit))
        take(CastBox(ray, ridges_[i], limit), ObstacleKind::kRidge, i);
    }
  }
  if (height_m < config_.post_height_m) {
    for (std::size_t i = 0; i < posts_.size(); ++i) {
      if (MayHitCircle(ray, posts_[i].centre_m, post_radius_m_[i], limit))
        take(CastBox(ray, posts_[i], limit), ObstacleKind::kPost, i);
    }
  }
  if (height_m < config_.wall_height_m) {
    for (std::size_t i = 0; i < walls_.size(); ++i)
      take(CastSegment(ray, walls_[i].first, walls_[i].second, limit), ObstacleKind::kWall, i);
  }
  return best;
}

AislePosition GreenhouseWorld::Locate(const Eigen::Vector2d& p_N_m) const {
  const Eigen::Vector2d d = p_N_m - config_.first_ridge_start_N_m;
  AislePosition a;
  a.along_m = d.dot(u_);
  const double left = d.dot(v_);
  const int last = std::max(0, config_.ridge_count - 2);
  a.aisle = std::clamp(static_cast<int>(std::floor(left / config_.ridge_spacing_m)), 0, last);
  a.lateral_m = left - (a.aisle + 0.5) * config_.ridge_spacing_m;
  a.between_ridges = a.along_m >= 0 && a.along_m <= config_.ridge_length_m;
  return a;
}

Eigen::Vector2d GreenhouseWorld::AislePoint(int aisle, double along_m, double lateral_m) const {
  return Map(along_m, (aisle + 0.5) * config_.ridge_spacing_m + lateral_m);
}

}  // namespace hil::world

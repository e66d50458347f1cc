#include "hil/estimator/guidance/row_follower.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hil::estimator::guidance {
namespace {

Eigen::Vector2d Rotate(const Eigen::Vector2d& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

RowFollower::RowFollower(const RowFollowerConfig& c, const PlannedPath& path)
    : config_(c), path_(path), pursuit_(c.pursuit), corrector_(c.corrector) {}

VehiclePose2d RowFollower::Anchored(const VehiclePose2d& e) const {
  VehiclePose2d a = e;
  a.p_EN_m = Rotate(e.p_EN_m, state_.anchor_yaw_rad) + state_.anchor_shift_m;
  a.yaw_rad = WrapPi(e.yaw_rad + state_.anchor_yaw_rad);
  return a;
}

void RowFollower::OnEstimate(GpsTime t, const VehiclePose2d& estimate) {
  double rate = 0;
  if (have_estimate_) {
    const double d = WrapPi(estimate.yaw_rad - last_yaw_rad_);
    yaw_unwrapped_rad_ += d;
    const double dt = std::chrono::duration<double>(t - last_t_).count();
    rate = dt > 0 ? d / dt : 0.0;
  } else {
    yaw_unwrapped_rad_ = estimate.yaw_rad;
  }
  last_yaw_rad_ = estimate.yaw_rad;
  last_t_ = t;
  estimate_ = estimate;
  have_estimate_ = true;
  corrector_.OnGyro({t, yaw_unwrapped_rad_, rate});
}

void RowFollower::OnRanges(const RangeSet& r) {
  if (!config_.correction) return;
  const double lim = config_.max_ridge_range_m;
  const bool beside = r.right_front_ok && r.right_rear_ok && r.left_front_ok && r.left_rear_ok &&
                      r.right_front_m <= lim && r.right_rear_m <= lim && r.left_front_m <= lim &&
                      r.left_rear_m <= lim;
  if (!beside) {  // out of the rows: no correction, none carried on (and no re-anchoring)
    corrector_.Abandon();
    was_correcting_ = false;
    anchor_fill_ = 0, anchor_pos_ = 0;
    return;
  }
  corrector_.OnRanges(r);
  const int n = std::clamp(config_.anchor_samples, 1, kMaxAnchorSamples);
  dp_ring_[static_cast<std::size_t>(anchor_pos_)] = corrector_.state().dp_m;
  ap_ring_[static_cast<std::size_t>(anchor_pos_)] = corrector_.state().ap_rad;
  anchor_pos_ = (anchor_pos_ + 1) % n;
  anchor_fill_ = std::min(anchor_fill_ + 1, n);
  const CorrectionMode m = corrector_.state().mode;
  const bool correcting = m == CorrectionMode::kHeading || m == CorrectionMode::kLateral ||
                          m == CorrectionMode::kRealign;
  if (was_correcting_ && m == CorrectionMode::kFollow) ReAnchor();
  was_correcting_ = correcting;
}

// The navigation's pose moved to where the ranges put the vehicle: DP left of the line (the
// corrector's DP > 0 is too far from the right ridge), heading AP left of the rows.
void RowFollower::ReAnchor() {
  if (!have_estimate_) return;
  const VehiclePose2d a = Anchored(estimate_);
  const PathProjection f = path_.Project(a.p_EN_m);
  if (path_.edge_kind(f.edge) != SegmentKind::kStraight) return;
  double dp = 0, ap = 0;
  for (int i = 0; i < anchor_fill_; ++i) {
    dp += dp_ring_[static_cast<std::size_t>(i)];
    ap += ap_ring_[static_cast<std::size_t>(i)];
  }
  dp /= std::max(anchor_fill_, 1);
  ap /= std::max(anchor_fill_, 1);
  const double dyaw = WrapPi(f.path_yaw_rad + ap - a.yaw_rad);
  // rotate about the vehicle, then shift across the path
  const Eigen::Vector2d normal_left(-f.tangent_EN.y(), f.tangent_EN.x());
  const Eigen::Vector2d shift = normal_left * (dp - f.cross_track_m);
  state_.anchor_yaw_rad = WrapPi(state_.anchor_yaw_rad + dyaw);
  state_.anchor_shift_m = Rotate(state_.anchor_shift_m - a.p_EN_m, dyaw) + a.p_EN_m + shift;
  ++state_.anchors;
}

VelocityCommand RowFollower::Command() {
  if (!have_estimate_) return {};
  const TrackingCommand c = pursuit_.Update(path_, Anchored(estimate_));
  state_.end_of_path = c.end_of_path;
  if (c.end_of_path) return {};
  const VelocityCommand base{config_.speed_mps, c.curvature_left_per_m * config_.speed_mps};
  return config_.correction ? corrector_.Command(base) : base;
}

WheelSpeeds WheelSpeedsFromSpeedAndYawRate(const DiffDrivePlatform& p, double v_mps,
                                           double w_radps) {
  const double half = 0.5 * w_radps * p.track_m;
  WheelSpeeds w{(v_mps - half) / p.wheel_radius_m, (v_mps + half) / p.wheel_radius_m};
  const double peak = std::max(std::abs(w.left_radps), std::abs(w.right_radps));
  if (peak > p.max_wheel_speed_radps && peak > 0) {
    const double k = p.max_wheel_speed_radps / peak;
    w.left_radps *= k;
    w.right_radps *= k;
  }
  return w;
}

}  // namespace hil::estimator::guidance

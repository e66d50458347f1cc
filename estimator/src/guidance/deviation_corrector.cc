#include "hil/estimator/guidance/deviation_corrector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hil::estimator::guidance {
namespace {

double Clamp(double v, double limit) { return std::clamp(v, -limit, limit); }

}  // namespace

DeviationCorrector::DeviationCorrector(const DeviationCorrectorConfig& config) : config_(config) {
  if (config_.window < 1 || config_.window > kMaxWindow || config_.within_needed < 1 ||
      config_.within_needed > config_.window)
    throw std::invalid_argument("deviation corrector: window/within_needed out of range");
  if (config_.range_rate_samples < 1 || config_.range_rate_samples >= kMaxRateSamples)
    throw std::invalid_argument("deviation corrector: range_rate_samples out of range");
  if (!(config_.p_dist_m > 0)) throw std::invalid_argument("deviation corrector: p_dist_m");
}

void DeviationCorrector::OnGyro(const GyroHeading& g) { gyro_ = g; }

void DeviationCorrector::Abandon() {
  state_.mode = CorrectionMode::kFollow;
  ring_fill_ = 0, ring_pos_ = 0, state_.within = 0;
}

void DeviationCorrector::PushWithin(bool within) {
  if (ring_fill_ == config_.window) state_.within -= within_ring_[ring_pos_] ? 1 : 0;
  within_ring_[ring_pos_] = within;
  state_.within += within ? 1 : 0;
  ring_pos_ = (ring_pos_ + 1) % config_.window;
  ring_fill_ = std::min(ring_fill_ + 1, config_.window);
}

bool DeviationCorrector::RecogniseTurn(const RangeSet& r) {
  // the mean range of each side, `range_rate_samples` back
  const double left = 0.5 * (r.left_front_m + r.left_rear_m);
  const double right = 0.5 * (r.right_front_m + r.right_rear_m);
  const int n = config_.range_rate_samples;
  const int back = (rate_pos_ - n + kMaxRateSamples) % kMaxRateSamples;
  bool opposite = false;
  if (rate_fill_ >= n) {
    const double dt = std::chrono::duration<double>(r.t - time_ring_[back]).count();
    if (dt > 0) {
      const double dl = (left - left_ring_[back]) / dt, dr = (right - right_ring_[back]) / dt;
      opposite = std::abs(dl) > config_.range_rate_mps && std::abs(dr) > config_.range_rate_mps &&
                 dl * dr < 0;
    }
  }
  left_ring_[rate_pos_] = left, right_ring_[rate_pos_] = right, time_ring_[rate_pos_] = r.t;
  rate_pos_ = (rate_pos_ + 1) % kMaxRateSamples;
  rate_fill_ = std::min(rate_fill_ + 1, kMaxRateSamples);
  const bool correcting = state_.mode == CorrectionMode::kHeading ||
                          state_.mode == CorrectionMode::kRealign ||
                          state_.mode == CorrectionMode::kLateral;
  // the corrector's own turns in place and its oblique swerves also change the sides oppositely
  // at a high yaw rate: not a road turn
  if (!correcting && opposite && std::abs(gyro_.yaw_rate_radps) > config_.turn_rate_radps) {
    if (r.t >= turn_until_) ++state_.turns;
    turn_until_ = r.t + config_.turn_hold;
  }
  return r.t < turn_until_;
}

void DeviationCorrector::OnRanges(const RangeSet& r) {
  const bool all_ok = r.right_front_ok && r.right_rear_ok && r.left_front_ok && r.left_rear_ok;
  const bool turning = all_ok && RecogniseTurn(r);
  if (turning) {
    state_.mode = CorrectionMode::kTurn;
    ring_fill_ = 0, ring_pos_ = 0, state_.within = 0;
    return;
  }
  if (state_.mode == CorrectionMode::kTurn) state_.mode = CorrectionMode::kFollow;
  if (!r.right_front_ok || !r.right_rear_ok) return;  // no DP, no AP: carry on as before
  const double ap = std::atan((r.right_front_m - r.right_rear_m) / config_.p_dist_m);
  state_.ap_rad = ap;
  const double rel = state_.mode == CorrectionMode::kLateral ? RelativeHeading() : ap;
  const double dp = 0.5 * (r.right_front_m + r.right_rear_m) * std::cos(rel) - config_.d_set_m;
  state_.dp_m = dp;
  PushWithin(std::abs(dp) <= config_.d_m_m);
  Decide(r, ap, dp);
}

void DeviationCorrector::Decide(const RangeSet& r, double ap_rad, double dp_m) {
  const bool left_ok = r.left_front_ok && r.left_rear_ok;
  switch (state_.mode) {
    case CorrectionMode::kFollow:
    case CorrectionMode::kTurn:
      if (!left_ok) return;
      if (std::abs(ap_rad) > config_.a_m_rad) {
        state_.mode = CorrectionMode::kHeading;
        target_yaw_rad_ = gyro_.yaw_rad - ap_rad;
        ++state_.heading_corrections;
      } else if (std::abs(dp_m) > config_.d_m_m) {
        state_.mode = CorrectionMode::kLateral;
        row_yaw_rad_ = gyro_.yaw_rad - ap_rad;
        ring_fill_ = 0, ring_pos_ = 0, state_.within = 0;  // count this correction's samples only
        ++state_.lateral_corrections;
      }
      return;
    case CorrectionMode::kHeading:
    case CorrectionMode::kRealign:
      if (std::abs(target_yaw_rad_ - gyro_.yaw_rad) <= config_.heading_tolerance_rad)
        state_.mode = CorrectionMode::kFollow;
      return;
    case CorrectionMode::kLateral:
      if (ring_fill_ >= config_.window && state_.within >= config_.within_needed) {
        state_.mode = CorrectionMode::kRealign;
        target_yaw_rad_ = row_yaw_rad_;
      }
      return;
  }
}

VelocityCommand DeviationCorrector::Command(const VelocityCommand& base) const {
  const double w_max = config_.max_turn_rate_radps;
  switch (state_.mode) {
    case CorrectionMode::kHeading:
    case CorrectionMode::kRealign:
      return {0.0, Clamp(config_.heading_gain_per_s * (target_yaw_rad_ - gyro_.yaw_rad), w_max)};
    case CorrectionMode::kLateral: {
      // DP > 0: too far from the right ridge: head right of the rows, at most 45°
      const double scale = std::min(1.0, std::abs(state_.dp_m) / config_.taper_offset_m);
      const double want = -std::copysign(config_.approach_rad * scale, state_.dp_m);
      return {base.v_mps, Clamp(config_.heading_gain_per_s * (want - RelativeHeading()), w_max)};
    }
    case CorrectionMode::kFollow:
    case CorrectionMode::kTurn:
      break;
  }
  return base;
}

}  // namespace hil::estimator::guidance

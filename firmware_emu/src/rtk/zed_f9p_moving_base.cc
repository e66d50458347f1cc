// The ZED-F9P as the rover of a moving base (dual-antenna heading): the moving base's frames on
// UART2 and the baseline between the two antennas in NAV-RELPOSNED (zed_f9p_device.h).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/rtk/zed_f9p_device.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;
using gnss::ubx::CarrSoln;

}  // namespace

void ZedF9pDevice::MovingBaseEpoch(const TruthSample& truth) {
  // the moving base's epoch is the rover's: its frames go down the wire into UART2 now, and the
  // rover's solution of this epoch has them when the MSM's last byte is in before the output
  const std::vector<SerialMessage> sent = moving_base_->Epoch(truth);
  const Time last_byte = FeedUart2(sent, moving_base_->config().baud);
  moving_matched_ = last_byte <= truth.t + config_.output_lag;
}

void ZedF9pDevice::ApplyMovingBase(const TruthSample& truth, double dt_s, gnss::GnssFix& fix) {
  const Time t = truth.t;
  // rover antenna − moving-base antenna, ENU (the truth of the baseline)
  const Eigen::Vector3d d_N =
      truth.q_NB * (config_.model.p_BA_B_m - moving_base_->config().p_BA_B_m);
  rtk_.config().dgnss_timeout_s = static_cast<double>(db_.Get(key::kNavspgConstrDgnssTo));
  rtk_.config().fixed_allowed = db_.Get(key::kNavhpgDgnssMode) == 3;
  const RoverRtkEpoch r =
      rtk_.Step(t, dt_s, fix.fix_type == gnss::FixType::k3D, d_N.norm(), last_.nav.sats);
  const CarrSoln carr = CarrSolnOf(r.state);
  // the absolute solution stays standalone
  last_.carr_soln = CarrSoln::kNone;
  last_.diff_soln = false;
  last_.correction_age_s = -1.0;
  fix.quality = !fix.valid() ? gnss::FixQuality::kInvalid : gnss::FixQuality::kGps;
  last_.is_moving = true;
  last_.rel_carr_soln = carr;
  last_.rel_diff_soln = carr != CarrSoln::kNone;
  if (timeline_.empty() || timeline_.back().carr_soln != carr)
    timeline_.push_back({t, carr, r.correction_age_s});
  if (carr != CarrSoln::kNone)
    ++(carr == CarrSoln::kFixed ? stats_.epochs_fixed : stats_.epochs_float);
  last_.ref_station_id = moving_ref_ ? moving_ref_->station_id : 0;
  last_.ref_pos_miss = !moving_ref_ || !moving_matched_;
  last_.ref_obs_miss = !moving_matched_;
  last_.relpos_valid = moving_ref_.has_value() && moving_matched_ && carr != CarrSoln::kNone;
  const Eigen::Vector3d rel_N = d_N + r.error_N_m;
  last_.rel_pos_NED_m = Eigen::Vector3d(rel_N.y(), rel_N.x(), -rel_N.z());
  last_.rel_acc_NED_m = Eigen::Vector3d(r.sigma_h_m, r.sigma_h_m, r.sigma_v_m);
  const double horizontal_m = std::hypot(rel_N.x(), rel_N.y());
  last_.acc_heading_deg = carr == CarrSoln::kNone || horizontal_m <= 0
                              ? 0.0
                              : std::atan2(r.sigma_h_m, horizontal_m) * 180.0 / std::numbers::pi;
  last_.heading_valid =
      last_.relpos_valid && last_.acc_heading_deg <= config_.heading_valid_max_acc_deg;
  if (!last_.heading_valid) return;
  // what the heading is worth: against the truth of the baseline (the encoder's atan2)
  const double err_deg =
      std::remainder(std::atan2(rel_N.x(), rel_N.y()) - std::atan2(d_N.x(), d_N.y()),
                     2 * std::numbers::pi) *
      180.0 / std::numbers::pi;
  ++stats_.heading_valid_epochs;
  stats_.heading_error_sum_sq_deg2 += err_deg * err_deg;
  stats_.heading_error_max_deg = std::max(stats_.heading_error_max_deg, std::abs(err_deg));
  stats_.acc_heading_sum_deg += last_.acc_heading_deg;
}

}  // namespace hil::rtk

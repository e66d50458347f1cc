#include "hil/truth/vehicle.h"

#include <cmath>
#include <random>

namespace hil::truth {

VehicleParams VehicleParams::GreenhousePlatform() { return VehicleParams{}; }

VehicleParams VehicleParams::Tractor() {
  VehicleParams p;
  p.wheelbase_m = 2.3;
  p.track_m = 1.6;
  p.max_steer_deg = 35;
  p.max_steer_rate_dps = 20;
  p.steer_lag_s = 0.3;
  p.speed_lag_s = 1.0;
  return p;
}

VehicleParams VehicleParams::DiffDrive() {
  VehicleParams p;
  p.model = Model::kDiffDrive;
  p.track_m = 0.5;
  p.speed_lag_s = 0.3;
  p.yaw_rate_lag_s = 0.2;
  p.max_yaw_rate_dps = 45;
  return p;
}

VehicleParams VehicleParams::SkidSteer() {
  VehicleParams p = DiffDrive();
  p.model = Model::kSkidSteer;
  p.icr_expansion = 1.5;
  p.icr_offset_m = 0.05;
  return p;
}

WheelGroundSpeeds WheelSpeedsOf(const VehicleParams& p, double v_mps, double yaw_rate_radps) {
  const double half = p.icr_track_m() / 2;
  return {v_mps - yaw_rate_radps * half, v_mps + yaw_rate_radps * half};
}

PlanarBodyVelocity BodyVelocityOf(const VehicleParams& p, double left_mps, double right_mps) {
  PlanarBodyVelocity b;
  b.yaw_rate_radps = (right_mps - left_mps) / p.icr_track_m();
  b.forward_mps = (left_mps + right_mps) / 2;  // symmetric ICRs: (v_r·y_l − v_l·y_r)/(y_l − y_r)
  b.lateral_mps = p.lateral_speed_mps(b.yaw_rate_radps);
  return b;
}

namespace {
constexpr double kSpeedGridS = 0.1;
}  // namespace

SpeedVariation::SpeedVariation(double std, double tau_s, std::uint64_t seed)
    : std_(std), phi_(tau_s > 0 ? std::exp(-kSpeedGridS / tau_s) : 0.0), state_(seed) {}

double SpeedVariation::Factor(double t_s) {
  if (std_ <= 0) return 1.0;
  const double pos = std::max(t_s, 0.0) / kSpeedGridS;
  const auto i = static_cast<std::size_t>(pos);
  if (x_.size() < i + 2) {
    std::mt19937_64 rng(state_);
    std::normal_distribution<double> normal(0.0, 1.0);
    // one engine for the whole grid, re-seeded from the stored state each time the grid grows:
    // draw the next values from a stream indexed by grid position (seed + index)
    while (x_.size() < i + 2) {
      rng.seed(state_ + x_.size());
      const double w = normal(rng);
      normal.reset();
      x_.push_back(x_.empty() ? std_ * w
                              : phi_ * x_.back() + std_ * std::sqrt(1 - phi_ * phi_) * w);
    }
  }
  const double f = pos - static_cast<double>(i);
  return 1.0 + (1 - f) * x_[i] + f * x_[i + 1];
}

}  // namespace hil::truth

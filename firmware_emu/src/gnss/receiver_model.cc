#include "hil/firmware_emu/gnss/receiver_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/gnss/geodesy.h"

namespace hil::gnss {
namespace {

constexpr double kBurstCorrelationTime_s = 2.0;

}  // namespace

ReceiverModel::ReceiverModel(const ReceiverModelConfig& config, std::uint64_t seed,
                             std::uint64_t common_seed)
    : config_(config), rng_(seed), common_rng_(common_seed != 0 ? common_seed : seed + 1) {}

void ReceiverModel::Advance(Eigen::Vector3d& state, std::mt19937_64& rng,
                            std::normal_distribution<double>& normal, double phi, bool first) {
  const double q = std::sqrt(1.0 - phi * phi);
  for (int i = 0; i < 3; ++i) state[i] = first ? normal(rng) : phi * state[i] + q * normal(rng);
}

GnssFix ReceiverModel::Calc(const TruthSample& truth, UnixTime utc, double dt_s,
                            const ErrorInputs& in) {
  // unit-variance processes; the draw sequence is the same whatever the inputs
  const bool first = !started_;
  started_ = true;
  Advance(common_, common_rng_, common_normal_, std::exp(-dt_s / config_.correlation_time_s),
          first);
  Advance(own_, rng_, normal_, std::exp(-dt_s / config_.correlation_time_s), first);
  Advance(burst_, rng_, normal_, std::exp(-dt_s / kBurstCorrelationTime_s), first);
  const double c = std::clamp(config_.common_fraction, 0.0, 1.0);
  const Eigen::Vector3d unit = std::sqrt(c) * common_ + std::sqrt(1.0 - c) * own_;
  const Eigen::Vector3d sigma(config_.horizontal_sigma_m * in.h_scale,
                              config_.horizontal_sigma_m * in.h_scale,
                              config_.vertical_sigma_m * in.v_scale);
  err_N_m_ = sigma.cwiseProduct(unit) + in.multipath_sigma_m * burst_ + in.offset_N_m;

  // antenna position and velocity (lever arm rotated into ENU, plus ω × r)
  const Eigen::Matrix3d R_NB = truth.q_NB.toRotationMatrix();
  const Eigen::Vector3d p_BA_N = R_NB * config_.p_BA_B_m;
  const Eigen::Vector3d v_A_N =
      truth.v_NB_N_mps + R_NB * truth.w_NB_B_radps.cross(config_.p_BA_B_m);

  // small ENU offsets → geodetic increments on the ellipsoid
  const double lat = truth.lat_deg * std::numbers::pi / 180.0;
  const double s = std::sin(lat);
  const double w = std::sqrt(1.0 - kWgs84E2 * s * s);
  const double rn = kWgs84A_m / w;                               // prime vertical radius
  const double rm = kWgs84A_m * (1.0 - kWgs84E2) / (w * w * w);  // meridian radius
  const Eigen::Vector3d d_N = p_BA_N + err_N_m_;

  GnssFix fix;
  fix.t_validity = truth.t;
  fix.utc = utc;
  fix.fix_type = FixType::k3D;
  fix.quality = FixQuality::kGps;
  fix.lat_deg = truth.lat_deg + d_N.y() / (rm + truth.height_m) * 180.0 / std::numbers::pi;
  fix.lon_deg =
      truth.lon_deg + d_N.x() / ((rn + truth.height_m) * std::cos(lat)) * 180.0 / std::numbers::pi;
  fix.height_m = truth.height_m + d_N.z();
  fix.geoid_separation_m = config_.geoid ? config_.geoid->SeparationAt_m(fix.lat_deg, fix.lon_deg)
                                         : config_.geoid_separation_m;
  const double sv = config_.velocity_sigma_mps * in.h_scale;
  fix.vel_e_mps = v_A_N.x() + sv * normal_(rng_);
  fix.vel_n_mps = v_A_N.y() + sv * normal_(rng_);
  fix.vel_d_mps = -v_A_N.z() + sv * normal_(rng_);
  const double h_sig = std::hypot(sigma.x(), sigma.y());
  const double burst_h = in.multipath_sigma_m * std::numbers::sqrt2;
  fix.h_acc_m = std::hypot(h_sig, burst_h);
  fix.v_acc_m = std::hypot(sigma.z(), in.multipath_sigma_m);
  if (in.extra_h_acc_m > 0.0) fix.h_acc_m = std::hypot(fix.h_acc_m, in.extra_h_acc_m);
  if (in.extra_v_acc_m > 0.0) fix.v_acc_m = std::hypot(fix.v_acc_m, in.extra_v_acc_m);
  fix.p_acc_m = std::hypot(fix.h_acc_m, fix.v_acc_m);
  fix.s_acc_mps = sv * std::sqrt(3.0);
  const double gs = fix.ground_speed_mps();
  fix.heading_acc_deg =
      gs > 1e-3
          ? std::min(180.0, std::atan2(sv * std::numbers::sqrt2, gs) * 180.0 / std::numbers::pi)
          : 180.0;
  return fix;
}

}  // namespace hil::gnss

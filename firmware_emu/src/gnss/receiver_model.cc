#include "hil/firmware_emu/gnss/receiver_model.h"

#include <cmath>
#include <numbers>

namespace hil::gnss {
namespace {

constexpr double kWgs84A_m = 6378137.0;
constexpr double kWgs84E2 = 6.69437999014e-3;

}  // namespace

ReceiverModel::ReceiverModel(const ReceiverModelConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed) {}

GnssFix ReceiverModel::Calc(const TruthSample& truth, std::int64_t unix_ns, double dt_s) {
  const Eigen::Vector3d sigma(config_.horizontal_sigma_m, config_.horizontal_sigma_m,
                              config_.vertical_sigma_m);
  if (!started_) {
    // stationary start: draw from the steady-state distribution
    for (int i = 0; i < 3; ++i) err_N_m_[i] = sigma[i] * normal_(rng_);
    started_ = true;
  } else {
    const double phi = std::exp(-dt_s / config_.correlation_time_s);
    const double q = std::sqrt(1.0 - phi * phi);
    for (int i = 0; i < 3; ++i) err_N_m_[i] = phi * err_N_m_[i] + q * sigma[i] * normal_(rng_);
  }

  // antenna position and velocity (lever arm rotated into ENU, plus ω × r)
  const Eigen::Matrix3d R_NB = truth.q_NB.toRotationMatrix();
  const Eigen::Vector3d p_BA_N = R_NB * config_.p_BA_B_m;
  const Eigen::Vector3d v_A_N = truth.v_NB_N_mps + R_NB * truth.w_NB_B_radps.cross(config_.p_BA_B_m);

  // small ENU offsets → geodetic increments on the ellipsoid
  const double lat = truth.lat_deg * std::numbers::pi / 180.0;
  const double s = std::sin(lat);
  const double w = std::sqrt(1.0 - kWgs84E2 * s * s);
  const double rn = kWgs84A_m / w;                          // prime vertical radius
  const double rm = kWgs84A_m * (1.0 - kWgs84E2) / (w * w * w);  // meridian radius
  const Eigen::Vector3d d_N = p_BA_N + err_N_m_;

  GnssFix fix;
  fix.t_validity = truth.t;
  fix.unix_ns = unix_ns;
  fix.fix_type = FixType::k3D;
  fix.quality = FixQuality::kGps;
  fix.lat_deg = truth.lat_deg + d_N.y() / (rm + truth.height_m) * 180.0 / std::numbers::pi;
  fix.lon_deg = truth.lon_deg + d_N.x() / ((rn + truth.height_m) * std::cos(lat)) * 180.0 / std::numbers::pi;
  fix.height_m = truth.height_m + d_N.z();
  fix.geoid_separation_m = config_.geoid_separation_m;
  fix.vel_e_mps = v_A_N.x() + config_.velocity_sigma_mps * normal_(rng_);
  fix.vel_n_mps = v_A_N.y() + config_.velocity_sigma_mps * normal_(rng_);
  fix.vel_d_mps = -v_A_N.z() + config_.velocity_sigma_mps * normal_(rng_);
  fix.h_acc_m = config_.horizontal_sigma_m * std::numbers::sqrt2;
  fix.v_acc_m = config_.vertical_sigma_m;
  fix.s_acc_mps = config_.velocity_sigma_mps * std::numbers::sqrt2;
  fix.num_sv = config_.num_sv;
  fix.hdop = config_.hdop;
  fix.vdop = config_.vdop;
  fix.pdop = config_.pdop;
  return fix;
}

}  // namespace hil::gnss

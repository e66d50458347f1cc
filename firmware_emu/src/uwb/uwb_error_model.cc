#include "hil/firmware_emu/uwb/uwb_error_model.h"

#include <cmath>
#include <numbers>

namespace hil::uwb {
namespace {
constexpr int kInverseIterations = 8;
}  // namespace

double CubicErrorField::Evaluate_m(double x_m, double y_m) const {
  const double x2 = x_m * x_m, y2 = y_m * y_m;
  return c[0] * x2 * x_m + c[1] * x2 + c[2] * x_m + c[3] * y2 * y_m + c[4] * y2 + c[5] * y_m +
         c[6] * x2 * y_m + c[7] * x_m * y2 + c[8] * x_m * y_m + c[9];
}

CubicErrorField Paper003FieldX() {
  return {{0.00031, -0.00083, -0.0384, -0.00007, -0.00022, 0.0016, -0.000044, 0.00005, -0.000101,
           0.0467}};
}
CubicErrorField Paper003FieldY() {
  return {{0.00012, -0.00059, -0.0027, 0.00015, 0.00042, -0.0420, 0.000021, 0.00001, -0.000167,
           0.0564}};
}

UwbErrorModel::UwbErrorModel(const UwbErrorConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed) {
  // Each wave: a random direction, a wavelength uniform in [min, max], a random phase. The sum
  // of N unit cosines with random phases has variance N/2: scaled by sqrt(2/N) below.
  for (auto& axis : waves_) {
    for (Wave& w : axis) {
      const double dir = 2 * std::numbers::pi * rng_.Uniform();
      const double lambda =
          config_.residual_wavelength_min_m +
          (config_.residual_wavelength_max_m - config_.residual_wavelength_min_m) * rng_.Uniform();
      w.k_radpm = (2 * std::numbers::pi / lambda) * Eigen::Vector2d(std::cos(dir), std::sin(dir));
      w.phase_rad = 2 * std::numbers::pi * rng_.Uniform();
    }
  }
}

Eigen::Vector2d UwbErrorModel::InverseCorrection(const Eigen::Vector2d& p_W_m) const {
  if (!config_.systematic_field) return p_W_m;
  Eigen::Vector2d m = p_W_m;
  for (int i = 0; i < kInverseIterations; ++i)
    m = p_W_m - Eigen::Vector2d(z_x_.Evaluate_m(m.x(), m.y()), z_y_.Evaluate_m(m.x(), m.y()));
  return m;
}

Eigen::Vector2d UwbErrorModel::Residual(const Eigen::Vector2d& p_W_m) const {
  const double scale = std::sqrt(2.0 / kResidualWaves);
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  for (int a = 0; a < 2; ++a) {
    double s = 0;
    for (const Wave& w : waves_[static_cast<std::size_t>(a)])
      s += std::cos(w.k_radpm.dot(p_W_m) + w.phase_rad);
    r[a] = config_.residual_sigma_m[a] * scale * s;
  }
  return r;
}

Eigen::Vector2d UwbErrorModel::Measure(const Eigen::Vector2d& p_W_true_m) {
  const Eigen::Vector2d noise(config_.white_sigma_m.x() * rng_.Normal(),
                              config_.white_sigma_m.y() * rng_.Normal());
  return InverseCorrection(p_W_true_m) + Residual(p_W_true_m) + noise;
}

NlosState UwbErrorModel::StepNlos(Time t, const Eigen::Vector2d& p_W_true_m, int anchor_count) {
  if (burst_.anchor >= 0 && t < burst_end_) return burst_;
  burst_ = {};
  for (const NlosZone& z : config_.nlos_zones) {
    if ((p_W_true_m - z.centre_W_m).norm() > z.radius_m) continue;
    if (rng_.Uniform() >= z.burst_probability) continue;
    burst_.anchor = static_cast<int>(rng_.Uniform() * anchor_count) % anchor_count;
    burst_.bias_m = z.bias_m + z.bias_sigma_m * std::fabs(rng_.Normal());
    burst_end_ = t + DurationFromSeconds(z.burst_duration_s);
    break;
  }
  return burst_;
}

}  // namespace hil::uwb

#include "hil/firmware_emu/gnss/sky_shading.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include <Eigen/Dense>

#include "hil/firmware_emu/angles.h"

namespace hil::gnss {
namespace {

constexpr double kMaxAlpha = 0.95;  // two-path formulas beyond this: the fade ends tracking

double DbFromAmplitude(double a) {
  return a > 0.0 ? 20.0 * std::log10(a) : -std::numeric_limits<double>::infinity();
}

// Geometry row of a used satellite (ComputeDops' convention: −line of sight in ENU, clock).
Eigen::Vector4d Row(const SatelliteView& s) {
  const double el = s.elev_deg * kDeg, az = s.azim_deg * kDeg;
  return {-std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), -std::sin(el), 1.0};
}

}  // namespace

SignalEffect ShadeSignal(const ShadingConfig& config, const Eigen::Vector3d& p_NA_N_m,
                         double az_deg, double el_deg) {
  SignalEffect fx;
  if (!config.active()) return fx;
  const world::SkyObstructions& w = *config.obstructions;
  const world::LineOfSight los = w.Trace(p_NA_N_m, az_deg * kDeg, el_deg * kDeg);
  const auto refl = w.StrongestReflection(p_NA_N_m, az_deg * kDeg, el_deg * kDeg);
  const double a_d = los.blocked ? 0.0 : std::pow(10.0, -los.loss_db / 20.0);
  const double a_r = refl ? refl->amplitude : 0.0;
  if (!refl) {
    fx.cno_change_db = DbFromAmplitude(a_d);
    return fx;
  }
  const double delta_m = refl->excess_path_m;
  const double phi = 2.0 * std::numbers::pi * delta_m / kGpsL1Wavelength_m;
  const std::complex<double> sum = a_d + a_r * std::polar(1.0, phi);
  fx.cno_change_db = DbFromAmplitude(std::abs(sum));
  if (a_d <= 0.0 || a_r >= a_d) {
    fx.nlos = true;
    fx.code_error_m = delta_m;
    fx.carrier_error_m = delta_m;
    if (a_d <= 0.0) fx.cno_change_db = DbFromAmplitude(a_r);
    return fx;
  }
  const double alpha = std::min(a_r / a_d, kMaxAlpha);
  const double half_spacing_m = 0.5 * config.correlator_spacing_chip * kGpsCaChip_m;
  const double delta_c = std::min(delta_m, half_spacing_m);
  fx.code_error_m = alpha * delta_c * std::cos(phi) / (1.0 + alpha * std::cos(phi));
  fx.carrier_error_m = kGpsL1Wavelength_m / (2.0 * std::numbers::pi) *
                       std::atan2(alpha * std::sin(phi), 1.0 + alpha * std::cos(phi));
  return fx;
}

RangeErrorSolution SolveRangeErrors(const std::vector<SatelliteView>& sats,
                                    const std::vector<double>& range_error_m) {
  RangeErrorSolution out;
  out.residual_m.assign(sats.size(), 0.0);
  int n = 0;
  for (const auto& s : sats) n += s.used ? 1 : 0;
  if (n < 3) return out;
  // 3 satellites: the height is held (east, north, clock), as in ComputeDops
  const int k = n == 3 ? 3 : 4;
  Eigen::MatrixXd h(n, k);
  Eigen::VectorXd e(n);
  int row = 0;
  for (std::size_t i = 0; i < sats.size(); ++i) {
    if (!sats[i].used) continue;
    const Eigen::Vector4d r = Row(sats[i]);
    h.row(row) = k == 4 ? Eigen::RowVectorXd(r.transpose())
                        : Eigen::RowVectorXd(Eigen::RowVector3d(r[0], r[1], r[3]));
    e[row++] = range_error_m[i];
  }
  const Eigen::MatrixXd hth = h.transpose() * h;
  if (std::abs(hth.determinant()) < 1e-9) return out;
  const Eigen::VectorXd dx = hth.ldlt().solve(h.transpose() * e);
  const Eigen::VectorXd res = e - h * dx;
  out.dp_N_m = Eigen::Vector3d(dx[0], dx[1], k == 4 ? dx[2] : 0.0);
  row = 0;
  for (std::size_t i = 0; i < sats.size(); ++i) {
    if (sats[i].used) out.residual_m[i] = res[row++];
  }
  out.sigma_m = n > k ? std::sqrt(res.squaredNorm() / (n - k)) : 0.0;
  out.valid = true;
  return out;
}

}  // namespace hil::gnss

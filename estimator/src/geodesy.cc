#include "hil/estimator/geodesy.h"

#include <cmath>
#include <numbers>

#include "hil/estimator/angles.h"

namespace hil::estimator {
namespace {}  // namespace

Eigen::Vector3d EcefFromLla(const Lla& g) {
  const double lat = g.lat_deg * kDeg, lon = g.lon_deg * kDeg;
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = kWgs84A_m / std::sqrt(1.0 - kWgs84E2 * s * s);
  return {(n + g.height_m) * c * std::cos(lon), (n + g.height_m) * c * std::sin(lon),
          (n * (1.0 - kWgs84E2) + g.height_m) * s};
}

Lla LlaFromEcef(const Eigen::Vector3d& p) {
  const double r_xy = std::hypot(p.x(), p.y());
  const double lon = std::atan2(p.y(), p.x()) / kDeg;
  if (r_xy < 1e-3) {  // on the polar axis (within a millimetre)
    const double n = kWgs84A_m / std::sqrt(1.0 - kWgs84E2);
    return {std::copysign(90.0, p.z()), lon, std::abs(p.z()) - n * (1.0 - kWgs84E2)};
  }
  // fixed-point iteration on latitude and height, carried in t = tan(lat) so that it needs
  // square roots only (sin² = t²/(1 + t²), 1/cos = √(1 + t²)): a profile of navd's output
  // found the trigonometric form's sin, cos and atan2 in every iteration costly
  double t = p.z() / (r_xy * (1.0 - kWgs84E2));
  double h = 0;
  for (int i = 0; i < 6; ++i) {
    const double sec2 = 1.0 + t * t;
    const double n = kWgs84A_m / std::sqrt(1.0 - kWgs84E2 * (t * t / sec2));
    h = r_xy * std::sqrt(sec2) - n;
    const double next = p.z() / (r_xy * (1.0 - kWgs84E2 * n / (n + h)));
    if (next == t) break;  // the exact fixed point: further iterations give the same bits
    t = next;
  }
  return {std::atan(t) / kDeg, lon, h};
}

double NormalGravity(double lat_deg, double height_m) {
  // Somigliana's formula on WGS-84, then the free-air gradient
  const double s2 = std::pow(std::sin(lat_deg * kDeg), 2);
  const double g0 = 9.7803253359 * (1.0 + 0.00193185265241 * s2) / std::sqrt(1.0 - kWgs84E2 * s2);
  return g0 - 3.086e-6 * height_m;
}

LocalTangentFrame::LocalTangentFrame(const Lla& origin)
    : origin_(origin), p_E0_m_(EcefFromLla(origin)) {
  const double lat = origin.lat_deg * kDeg, lon = origin.lon_deg * kDeg;
  const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
  // columns: east, north, up expressed in ECEF
  R_EN_ << -so, -sl * co, cl * co, co, -sl * so, cl * so, 0.0, cl, sl;
}

Eigen::Vector3d LocalTangentFrame::ToLocal(const Lla& g) const {
  return R_EN_.transpose() * (EcefFromLla(g) - p_E0_m_);
}

Lla LocalTangentFrame::ToLla(const Eigen::Vector3d& p_N_m) const {
  return LlaFromEcef(p_E0_m_ + R_EN_ * p_N_m);
}

Eigen::Vector3d LocalTangentFrame::w_IE_N() const {
  const double lat = origin_.lat_deg * kDeg;
  return {0.0, kEarthRate_radps * std::cos(lat), kEarthRate_radps * std::sin(lat)};
}

}  // namespace hil::estimator

#pragma once
// WGS84 geodetic coordinates to local east-north-up metres about an origin, and back (the frame
// of hil's scenarios and path files). Standard library only.
#include <array>
#include <cmath>

namespace hil_example {

inline constexpr double kWgs84A = 6378137.0;
inline constexpr double kWgs84E2 = 6.69437999014e-3;
inline constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

inline std::array<double, 3> Ecef(double lat_deg, double lon_deg, double h_m) {
  const double lat = lat_deg * kDegToRad, lon = lon_deg * kDegToRad;
  const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * std::sin(lat) * std::sin(lat));
  return {(n + h_m) * std::cos(lat) * std::cos(lon), (n + h_m) * std::cos(lat) * std::sin(lon),
          (n * (1.0 - kWgs84E2) + h_m) * std::sin(lat)};
}

class LocalFrame {
 public:
  LocalFrame(double lat_deg, double lon_deg, double h_m) : o_(Ecef(lat_deg, lon_deg, h_m)) {
    const double sl = std::sin(lat_deg * kDegToRad), cl = std::cos(lat_deg * kDegToRad);
    const double so = std::sin(lon_deg * kDegToRad), co = std::cos(lon_deg * kDegToRad);
    r_ = {{{-so, co, 0.0}, {-sl * co, -sl * so, cl}, {cl * co, cl * so, sl}}};
  }
  /// East, north, up metres of a geodetic point.
  std::array<double, 3> ToEnu(double lat_deg, double lon_deg, double h_m) const {
    const std::array<double, 3> p = Ecef(lat_deg, lon_deg, h_m);
    std::array<double, 3> enu{};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) enu[k] += r_[k][i] * (p[i] - o_[i]);
    return enu;
  }
  /// Latitude, longitude (degrees) and ellipsoidal height of a local point (fixed-point latitude,
  /// five turns: below 1e-9 rad near the ground).
  std::array<double, 3> ToLla(const std::array<double, 3>& enu) const {
    std::array<double, 3> x = o_;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) x[i] += r_[k][i] * enu[k];
    const double p = std::hypot(x[0], x[1]);
    double lat = std::atan2(x[2], p * (1.0 - kWgs84E2));
    for (int turn = 0; turn < 5; ++turn) {
      const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * std::sin(lat) * std::sin(lat));
      const double h = p / std::cos(lat) - n;
      lat = std::atan2(x[2], p * (1.0 - kWgs84E2 * n / (n + h)));
    }
    const double n = kWgs84A / std::sqrt(1.0 - kWgs84E2 * std::sin(lat) * std::sin(lat));
    return {lat / kDegToRad, std::atan2(x[1], x[0]) / kDegToRad, p / std::cos(lat) - n};
  }

 private:
  std::array<double, 3> o_;
  std::array<std::array<double, 3>, 3> r_{};
};

}  // namespace hil_example

#include "hil/firmware_emu/gnss/geodesy.h"

#include <cmath>
#include <numbers>

namespace hil::gnss {

Eigen::Vector3d EcefFromGeodetic(double lat_deg, double lon_deg, double height_m) {
  const double lat = lat_deg * std::numbers::pi / 180.0, lon = lon_deg * std::numbers::pi / 180.0;
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = kWgs84A_m / std::sqrt(1.0 - kWgs84E2 * s * s);
  return {(n + height_m) * c * std::cos(lon), (n + height_m) * c * std::sin(lon),
          (n * (1.0 - kWgs84E2) + height_m) * s};
}

Eigen::Matrix3d RotationEcefFromEnu(double lat_deg, double lon_deg) {
  const double lat = lat_deg * std::numbers::pi / 180.0, lon = lon_deg * std::numbers::pi / 180.0;
  const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
  Eigen::Matrix3d r;
  r << -so, -sl * co, cl * co,  //
      co, -sl * so, cl * so,    //
      0.0, cl, sl;
  return r;
}

}  // namespace hil::gnss

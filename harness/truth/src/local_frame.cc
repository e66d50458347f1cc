#include "hil/truth/local_frame.h"

#include <vector>

#include <GeographicLib/Geocentric.hpp>

namespace hil::truth {

LocalFrame::LocalFrame(const Geodetic& origin)
    : origin_(origin),
      lc_(origin.lat_deg, origin.lon_deg, origin.height_m, GeographicLib::Geocentric::WGS84()) {
  std::vector<double> m(9);
  GeographicLib::Geocentric::WGS84().Forward(origin_.lat_deg, origin_.lon_deg, origin_.height_m,
                                             p_E_origin_m_.x(), p_E_origin_m_.y(),
                                             p_E_origin_m_.z(), m);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R_EN_(i, j) = m[static_cast<std::size_t>(3 * i + j)];
}

Geodetic LocalFrame::ToGeodetic(const Eigen::Vector3d& p) const {
  Geodetic g;
  lc_.Reverse(p.x(), p.y(), p.z(), g.lat_deg, g.lon_deg, g.height_m);
  return g;
}

Eigen::Vector3d LocalFrame::FromGeodetic(const Geodetic& g) const {
  Eigen::Vector3d p;
  lc_.Forward(g.lat_deg, g.lon_deg, g.height_m, p.x(), p.y(), p.z());
  return p;
}

}  // namespace hil::truth

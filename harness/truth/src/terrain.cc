#include "hil/truth/terrain.h"

#include <cmath>
#include <numbers>
#include <random>

#include "hil/firmware_emu/angles.h"

namespace hil::truth {

Terrain::Terrain(const TerrainConfig& c) : z0_m_(c.height_m) {
  if (c.type != TerrainConfig::Type::kFlat) {
    const double g = std::tan(c.slope_deg * kDeg);
    const double az = c.uphill_heading_deg * kDeg;  // clockwise from north: (sin, cos) in ENU
    slope_ = g * Eigen::Vector2d(std::sin(az), std::cos(az));
  }
  if (c.type == TerrainConfig::Type::kRough) {
    // a seeded local generator: the same seed gives the same field on every platform
    std::mt19937_64 rng(c.seed);
    const auto uniform = [&rng](double lo, double hi) {
      return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    for (int i = 0; i < c.waves; ++i) {
      TerrainWave w;
      w.amplitude_m = c.amplitude_m;
      const double wavelength = uniform(c.min_wavelength_m, c.max_wavelength_m);
      const double dir = uniform(0, 2 * std::numbers::pi);
      w.k_radpm = 2 * std::numbers::pi / wavelength * Eigen::Vector2d(std::cos(dir), std::sin(dir));
      w.phase_rad = uniform(0, 2 * std::numbers::pi);
      waves_.push_back(w);
    }
  }
}

void Terrain::Evaluate(const Jet2& e, const Jet2& n, Jet2& z, Jet2& dz_de, Jet2& dz_dn) const {
  z = Jet2(z0_m_) + slope_.x() * e + slope_.y() * n;
  dz_de = Jet2(slope_.x());
  dz_dn = Jet2(slope_.y());
  for (const TerrainWave& w : waves_) {
    const Jet2 arg = w.k_radpm.x() * e + w.k_radpm.y() * n + Jet2(w.phase_rad);
    const Jet2 s = sin(arg), c = cos(arg);
    z += w.amplitude_m * s;
    dz_de += (w.amplitude_m * w.k_radpm.x()) * c;
    dz_dn += (w.amplitude_m * w.k_radpm.y()) * c;
  }
}

double Terrain::Height(const Eigen::Vector2d& p) const {
  Jet2 z, ze, zn;
  Evaluate(Jet2(p.x()), Jet2(p.y()), z, ze, zn);
  return z.v;
}

Eigen::Vector2d Terrain::Gradient(const Eigen::Vector2d& p) const {
  Jet2 z, ze, zn;
  Evaluate(Jet2(p.x()), Jet2(p.y()), z, ze, zn);
  return {ze.v, zn.v};
}

}  // namespace hil::truth

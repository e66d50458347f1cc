#include "hil/firmware_emu/gnss/constellation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Dense>

#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/gnss/geodesy.h"

namespace hil::gnss {
namespace {

constexpr double kMu_m3ps2 = 3.986005e14;
constexpr double kEarthRate_radps = 7.2921151467e-5;
constexpr double kGpsA_m = 26559700.0;
constexpr double kGpsIncl_rad = 55.0 * kDeg;
constexpr double kGeoRadius_m = 42164000.0;
constexpr double kTrackMinElev_deg = 2.0;  // below this the signal is not acquired

// Elevation and azimuth (deg) of an ECEF satellite position seen from an ECEF receiver.
void LookAngles(const Eigen::Vector3d& sat_e, const Eigen::Vector3d& rx_e,
                const Eigen::Matrix3d& r_en, double& elev_deg, double& azim_deg) {
  const Eigen::Vector3d los_n = r_en.transpose() * (sat_e - rx_e).normalized();
  elev_deg = std::asin(std::clamp(los_n.z(), -1.0, 1.0)) / kDeg;
  double az = std::atan2(los_n.x(), los_n.y()) / kDeg;
  if (az < 0) az += 360.0;
  azim_deg = az;
}

}  // namespace

struct Constellation::OrbitClock {
  double n_radps, orbit_s, sidereal_s;
  Eigen::Matrix3d r_incl;
  explicit OrbitClock(double gps_s)
      : n_radps(std::sqrt(kMu_m3ps2 / (kGpsA_m * kGpsA_m * kGpsA_m))),
        // the same for every orbit (hoisted: the same arithmetic, so the same bits)
        orbit_s(std::fmod(gps_s, 86400.0 * 365.25 * 4)),
        sidereal_s(std::fmod(gps_s, 86164.0905)),
        r_incl(Eigen::AngleAxisd(kGpsIncl_rad, Eigen::Vector3d::UnitX()).toRotationMatrix()) {}
};

Eigen::Vector3d Constellation::PositionEcef(const Orbit& o, const OrbitClock& clock) {
  const double u = o.anomaly0_rad + clock.n_radps * clock.orbit_s;
  const double raan = o.raan0_rad - kEarthRate_radps * clock.sidereal_s;
  const Eigen::Vector3d p_orb(kGpsA_m * std::cos(u), kGpsA_m * std::sin(u), 0.0);
  return Eigen::AngleAxisd(raan, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
         (clock.r_incl * p_orb);
}

std::vector<SatelliteEcef> Constellation::GpsPositionsEcef(double gps_s) const {
  const OrbitClock clock(gps_s);
  std::vector<SatelliteEcef> out;
  out.reserve(gps_.size());
  for (const Orbit& o : gps_) out.push_back({o.svid, PositionEcef(o, clock)});
  return out;
}

SatelliteEcef Constellation::GpsPositionEcef(std::size_t index, double gps_s) const {
  const Orbit& o = gps_.at(index);
  return {o.svid, PositionEcef(o, OrbitClock(gps_s))};
}

GpsEphemeris Constellation::Ephemeris(std::size_t index, double toe_gps_s) const {
  const Orbit& o = gps_.at(index);
  const OrbitClock clock(toe_gps_s);
  constexpr double kWeek_s = 604800.0;
  GpsEphemeris e;
  e.svid = o.svid;
  e.week = static_cast<int>(std::floor(toe_gps_s / kWeek_s));
  e.toe_s = toe_gps_s - e.week * kWeek_s;
  e.sqrt_a = std::sqrt(kGpsA_m);
  e.i0_rad = kGpsIncl_rad;
  // IS-GPS-200: u = M0 + n t_k (e = 0, ω = 0); Ω = Ω0 − Ω̇e (t_k + t_oe)
  e.m0_rad = std::remainder(o.anomaly0_rad + clock.n_radps * clock.orbit_s, 2 * std::numbers::pi);
  const double node_rad = o.raan0_rad - kEarthRate_radps * clock.sidereal_s;
  e.omega0_rad = std::remainder(node_rad + kEarthRate_radps * e.toe_s, 2 * std::numbers::pi);
  return e;
}

Constellation::Constellation(std::uint64_t seed) {
  // PRN assignment: a fixed permutation of 1..32 without two PRNs, so the sky looks like a real
  // one (not 1..30 in plane order). The seed varies only C/N0 offsets, not the geometry.
  std::vector<int> prns;
  for (int p = 1; p <= 32; ++p) {
    if (p != 4 && p != 12) prns.push_back(p);  // two unused PRNs, as in a real constellation
  }
  std::mt19937_64 perm_rng(0x5EED5EEDULL);
  std::shuffle(prns.begin(), prns.end(), perm_rng);
  std::mt19937_64 rng(seed ^ 0xC0115EEDULL);
  std::uniform_int_distribution<int> offset(-3, 3);
  for (int plane = 0; plane < 6; ++plane) {
    for (int slot = 0; slot < 5; ++slot) {
      Orbit o;
      o.svid = prns[static_cast<std::size_t>(plane * 5 + slot)];
      o.raan0_rad = (plane * 60.0 + 17.0) * kDeg;
      o.anomaly0_rad = (slot * 72.0 + plane * 24.0) * kDeg;
      o.cno_offset = offset(rng);
      gps_.push_back(o);
    }
  }
  sbas_ = {{120, -15.5}, {124, 21.5},  {126, 25.0},   {127, 55.0},  {128, 83.0},
           {129, 140.0}, {133, -98.0}, {135, -133.0}, {138, -107.3}};
}

std::vector<SatelliteView> Constellation::Sky(double gps_s, double lat_deg, double lon_deg,
                                              double height_m, const SkyConditions& cond) const {
  const Eigen::Vector3d rx_e = EcefFromGeodetic(lat_deg, lon_deg, height_m);
  const Eigen::Matrix3d r_en = RotationEcefFromEnu(lat_deg, lon_deg);
  const OrbitClock clock(gps_s);
  std::vector<SatelliteView> out;
  out.reserve(gps_.size() + sbas_.size());
  for (const Orbit& o : gps_) {
    const Eigen::Vector3d p_e = PositionEcef(o, clock);
    SatelliteView s;
    s.svid = o.svid;
    LookAngles(p_e, rx_e, r_en, s.elev_deg, s.azim_deg);
    if (s.elev_deg < 0) continue;
    // C/N0: rises with elevation; a slow deterministic ripple stands in for multipath fading
    const double ripple = 1.5 * std::sin(gps_s / 37.0 + o.svid);
    double cno = 34.0 + 12.0 * std::sin(s.elev_deg * kDeg) + o.cno_offset + ripple;
    if (cond.shade) cond.shade(s, cno);
    s.cno_dbhz = std::isfinite(cno) && cno > 0 ? static_cast<int>(std::lround(cno)) : 0;
    out.push_back(s);
  }
  if (cond.sbas_enabled) {
    std::vector<SatelliteView> geo;
    for (const auto& [svid, lon] : sbas_) {
      const Eigen::Vector3d p_e(kGeoRadius_m * std::cos(lon * kDeg),
                                kGeoRadius_m * std::sin(lon * kDeg), 0.0);
      SatelliteView s;
      s.svid = svid;
      s.sbas = true;
      LookAngles(p_e, rx_e, r_en, s.elev_deg, s.azim_deg);
      if (s.elev_deg < 10.0) continue;  // SBAS signals are weak near the horizon
      double cno = 31.0 + 8.0 * std::sin(s.elev_deg * kDeg);
      if (cond.shade) cond.shade(s, cno);
      s.cno_dbhz = std::isfinite(cno) && cno > 0 ? static_cast<int>(std::lround(cno)) : 0;
      geo.push_back(s);
    }
    // the receiver searches only maxSBAS of them: the highest
    std::sort(geo.begin(), geo.end(),
              [](const auto& a, const auto& b) { return a.elev_deg > b.elev_deg; });
    for (std::size_t i = 0; i < geo.size() && static_cast<int>(i) < cond.max_sbas; ++i)
      out.push_back(geo[i]);
  }
  // channel assignment: highest elevation first, GPS before SBAS
  std::vector<SatelliteView*> order;
  for (auto& s : out) order.push_back(&s);
  std::sort(order.begin(), order.end(), [](const SatelliteView* a, const SatelliteView* b) {
    if (a->sbas != b->sbas) return !a->sbas;
    return a->elev_deg > b->elev_deg;
  });
  int channel = 0;
  for (SatelliteView* s : order) {
    const bool receivable = !cond.sky_blocked &&
                            s->elev_deg >= std::max(kTrackMinElev_deg, cond.blocked_below_deg) &&
                            s->cno_dbhz > 0 && s->cno_dbhz >= cond.track_min_dbhz;
    if (!receivable || channel >= cond.max_channels) {
      s->cno_dbhz = 0;
      s->quality = receivable ? 0 : 1;  // idle (no free channel) or searching
      continue;
    }
    s->channel = channel++;
    s->tracked = true;
    s->used =
        !s->sbas && s->elev_deg >= cond.elevation_mask_deg && s->cno_dbhz >= cond.nav_min_dbhz;
    s->quality = s->used ? 7 : 4;
  }
  std::sort(out.begin(), out.end(),
            [](const SatelliteView& a, const SatelliteView& b) { return a.svid < b.svid; });
  return out;
}

Dops ComputeDops(const std::vector<SatelliteView>& sats) {
  std::vector<Eigen::Vector4d> rows;
  for (const auto& s : sats) {
    if (!s.used) continue;
    const double el = s.elev_deg * kDeg, az = s.azim_deg * kDeg;
    rows.emplace_back(-std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), -std::sin(el),
                      1.0);
  }
  Dops d;
  if (rows.size() == 3) {
    // 2D solution: the height is held, east, north and clock are solved
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    for (const auto& r : rows) {
      const Eigen::Vector3d r2(r[0], r[1], r[3]);
      h += r2 * r2.transpose();
    }
    if (std::abs(h.determinant()) < 1e-9) return d;
    const Eigen::Matrix3d q = h.inverse();
    d.edop = std::sqrt(q(0, 0));
    d.ndop = std::sqrt(q(1, 1));
    d.hdop = d.pdop = std::sqrt(q(0, 0) + q(1, 1));
    d.tdop = std::sqrt(q(2, 2));
    d.gdop = std::sqrt(q.trace());
    d.valid = true;
    return d;
  }
  if (rows.size() < 4) return d;
  Eigen::Matrix4d h = Eigen::Matrix4d::Zero();
  for (const auto& r : rows) h += r * r.transpose();
  const Eigen::Matrix4d q = h.inverse();
  d.edop = std::sqrt(q(0, 0));
  d.ndop = std::sqrt(q(1, 1));
  d.vdop = std::sqrt(q(2, 2));
  d.tdop = std::sqrt(q(3, 3));
  d.hdop = std::sqrt(q(0, 0) + q(1, 1));
  d.pdop = std::sqrt(q(0, 0) + q(1, 1) + q(2, 2));
  d.gdop = std::sqrt(q.trace());
  d.valid = true;
  return d;
}

}  // namespace hil::gnss

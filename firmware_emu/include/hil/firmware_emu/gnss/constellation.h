#pragma once
/// @file
/// @system
/// name: Constellation (synthetic GPS + SBAS sky for the receiver emulator)
/// input: GPS time (s since the GPS epoch) and the antenna's geodetic position
/// output: the satellites in view with elevation, azimuth, C/N0, channel, tracked/used flags;
///         DOPs of the used set
/// rate: on demand (each navigation epoch)
/// @endsystem
///
/// The GPS part is a nominal Walker-like constellation: 30 satellites on circular orbits
/// (semi-major axis 26 559.7 km, inclination 55°, 6 planes 60° apart, 5 slots each with a phase
/// offset between planes), rotating under the Earth so that elevations and azimuths change with
/// date, time and place as a real sky does (repeat ≈ one sidereal day). It is not the broadcast
/// almanac of any date. SBAS satellites are geostationary at the longitudes of the real systems
/// (EGNOS, WAAS, MSAS, GAGAN; approximate). C/N0 grows with elevation (≈ 34–46 dBHz), with a fixed
/// per-satellite offset and a slow deterministic ripple.

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace hil::gnss {

/// One satellite as the receiver sees it at an epoch.
struct SatelliteView {
  int svid = 0;  ///< UBX numbering: GPS 1–32, SBAS 120–158
  bool sbas = false;
  double elev_deg = 0, azim_deg = 0;
  int cno_dbhz = 0;         ///< 0 when not tracked
  int channel = 255;        ///< 0–15 when assigned to a channel, 255 otherwise
  bool tracked = false;     ///< code (and carrier) lock
  bool used = false;        ///< in the navigation solution
  bool orbit_known = true;  ///< elevation/azimuth known (almanac or ephemeris)
  int quality = 0;          ///< UBX qualityInd 0–7
  double pr_res_m = 0;      ///< pseudorange residual (used satellites)
  /// Multipath of the sky's obstructions (SkyShading; 0 under an open sky): range errors of the
  /// code and the carrier, and whether only a reflection arrives.
  double code_multipath_m = 0, carrier_multipath_m = 0;
  bool nlos = false;
  int nmea_id() const { return sbas ? svid - 87 : svid; }  ///< NMEA numbering (SBAS 120 → 33)
};

/// Dilutions of precision of a satellite geometry.
struct Dops {
  double gdop = 99.99, pdop = 99.99, tdop = 99.99, vdop = 99.99, hdop = 99.99, ndop = 99.99,
         edop = 99.99;
  bool valid = false;  ///< false with fewer than 4 satellites
};

/// What limits the sky at an epoch (receiver settings and scripted faults).
struct SkyConditions {
  double elevation_mask_deg = 5.0;  ///< CFG-NAV5 minElev: satellites below are not used
  double blocked_below_deg = 0.0;   ///< scripted obstruction: nothing below this is received
  bool sky_blocked = false;         ///< scripted outage: nothing is received
  bool sbas_enabled = true;         ///< CFG-SBAS mode bit 0
  int max_sbas = 3;                 ///< CFG-SBAS maxSBAS: SBAS satellites searched
  int max_channels = 16;            ///< tracking channels (u-blox 5: 16 for GPS/SBAS, UNVERIFIED)
  /// Obstructions of the sky (SkyShading): called for each satellite in view with its nominal
  /// C/N0 (dBHz), which it may lower, and its multipath fields to fill. Empty: open sky.
  std::function<void(SatelliteView&, double& cno_dbhz)> shade;
  double track_min_dbhz = 0;  ///< C/N0 below which a satellite is not tracked
  double nav_min_dbhz = 0;    ///< C/N0 below which a tracked satellite is not used
};

/// One GPS satellite's position in ECEF (WGS-84, Earth-fixed at the instant asked).
struct SatelliteEcef {
  int svid = 0;  ///< GPS PRN 1–32
  Eigen::Vector3d p_E_m = Eigen::Vector3d::Zero();
};

/// A GPS satellite's orbit as broadcast ephemeris (IS-GPS-200 §20.3.3.4.3 quantities), for an
/// RTK engine that needs navigation data (a RINEX navigation file, RTCM 1019). Our orbits are
/// circular with a fixed node in the rotating frame, so e, ω, Δn, Ω̇, IDOT and the harmonic
/// corrections are 0 and the satellites have no clock error (a_f0 = a_f1 = a_f2 = 0, T_GD = 0):
/// the IS-GPS-200 algorithm with these elements gives GpsPositionEcef()'s positions.
struct GpsEphemeris {
  int svid = 0;
  int week = 0;           ///< GPS week of t_oe (full, not modulo 1024)
  double toe_s = 0;       ///< t_oe, seconds of the week
  double sqrt_a = 0;      ///< √A (√m)
  double i0_rad = 0;      ///< inclination at t_oe
  double omega0_rad = 0;  ///< Ω0: longitude of the ascending node at the week's start
  double m0_rad = 0;      ///< mean anomaly at t_oe (argument of latitude: e = 0, ω = 0)
};

class Constellation {
 public:
  explicit Constellation(std::uint64_t seed);
  /// The sky at GPS time `gps_s` (seconds since 1980-01-06) over the antenna, sorted by svid.
  std::vector<SatelliteView> Sky(double gps_s, double lat_deg, double lon_deg, double height_m,
                                 const SkyConditions& cond) const;
  /// ECEF positions of every GPS satellite at GPS time `gps_s` (above and below any horizon), in
  /// the order of the orbit table. The positions Sky() derives its elevations from (same bits).
  std::vector<SatelliteEcef> GpsPositionsEcef(double gps_s) const;
  /// Number of GPS orbits (the index range of GpsPositionEcef).
  std::size_t gps_count() const { return gps_.size(); }
  /// ECEF position of the GPS satellite of orbit `index` at GPS time `gps_s`.
  SatelliteEcef GpsPositionEcef(std::size_t index, double gps_s) const;
  /// The broadcast ephemeris of orbit `index` with reference time `toe_gps_s` (s since the GPS
  /// epoch): valid around it while neither the 4-year orbit clock nor the sidereal day of the
  /// node wraps (the model's own discontinuities).
  GpsEphemeris Ephemeris(std::size_t index, double toe_gps_s) const;

 private:
  struct Orbit {
    int svid;
    double raan0_rad, anomaly0_rad;
    int cno_offset;
  };
  struct OrbitClock;  // the per-epoch terms shared by every orbit
  static Eigen::Vector3d PositionEcef(const Orbit& o, const OrbitClock& clock);
  std::vector<Orbit> gps_;
  std::vector<std::pair<int, double>> sbas_;  // svid, longitude deg
};

/// DOPs of the used satellites (ENU geometry, clock as the fourth unknown).
Dops ComputeDops(const std::vector<SatelliteView>& sats);

}  // namespace hil::gnss

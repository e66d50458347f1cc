#include "hil/firmware_emu/rtk/base_observables.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/gnss/geodesy.h"

namespace hil::rtk {
namespace {

constexpr double kLight_mps = 299792458.0;
constexpr double kEarthRate_radps = 7.2921151467e-5;
constexpr double kRangeRateStep_s = 0.05;  // central difference of the range

// Black & Eisner (1984) tropospheric mapping function.
double TropoMapping(double elev_rad) {
  const double s = std::sin(elev_rad);
  return 1.001 / std::sqrt(0.002001 + s * s);
}

// Thin-shell ionospheric mapping function (slant / vertical).
double IonoMapping(double elev_rad, double shell_m) {
  const double x = gnss::kWgs84A_m * std::cos(elev_rad) / (gnss::kWgs84A_m + shell_m);
  return 1.0 / std::sqrt(1.0 - x * x);
}

}  // namespace

BaseObservables::BaseObservables(const BaseObservablesConfig& config, double lat_deg,
                                 double lon_deg, double height_m, std::uint64_t seed)
    : config_(config),
      antenna_E_m_(gnss::EcefFromGeodetic(lat_deg, lon_deg, height_m)),
      lat_deg_(lat_deg),
      lon_deg_(lon_deg),
      height_m_(height_m),
      rng_(seed ^ 0xBA5EBA5EULL) {}

void BaseObservables::MoveTo(double lat_deg, double lon_deg, double height_m) {
  antenna_E_m_ = gnss::EcefFromGeodetic(lat_deg, lon_deg, height_m);
  lat_deg_ = lat_deg;
  lon_deg_ = lon_deg;
  height_m_ = height_m;
}

double BaseObservables::GeometricRange(const gnss::Constellation& sky, std::size_t index,
                                       double gps_s, Eigen::Vector3d& sat_E_m) const {
  double tau_s = 0.075;  // start near the mean GPS signal flight time
  double range_m = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d p_emit = sky.GpsPositionEcef(index, gps_s - tau_s).p_E_m;
    // the Earth turns by ω·τ while the signal flies: the emission position in the frame of
    // reception
    sat_E_m = Eigen::AngleAxisd(-kEarthRate_radps * tau_s, Eigen::Vector3d::UnitZ()) * p_emit;
    range_m = (sat_E_m - antenna_E_m_).norm();
    tau_s = range_m / kLight_mps;
  }
  return range_m;
}

double BaseObservables::Multipath(double amplitude_m, int prn, std::size_t signal, double gps_s,
                                  double elev_rad) const {
  if (amplitude_m == 0) return 0;
  // a phase per satellite and signal (ours: any fixed spread) so the errors do not align
  const double phase_rad = 2.39996 * prn + 1.3 * static_cast<double>(signal);
  return amplitude_m * std::cos(elev_rad) *
         std::sin(2.0 * std::numbers::pi * gps_s / config_.multipath_period_s + phase_rad);
}

SatelliteObservation BaseObservables::Satellite(const gnss::Constellation& sky, std::size_t index,
                                                double gps_s, double elev_deg, double azim_deg,
                                                const ObserveConditions& cond) {
  SatelliteObservation o;
  o.prn = sky.GpsPositionEcef(index, gps_s).svid;
  o.elevation_deg = elev_deg;
  o.azimuth_deg = azim_deg;
  Eigen::Vector3d sat_E_m;
  o.geometric_range_m = GeometricRange(sky, index, gps_s, sat_E_m);
  Eigen::Vector3d unused;
  const double rate_mps = (GeometricRange(sky, index, gps_s + kRangeRateStep_s, unused) -
                           GeometricRange(sky, index, gps_s - kRangeRateStep_s, unused)) /
                              (2 * kRangeRateStep_s) +
                          kLight_mps * cond.clock_drift;
  const double clock_m = kLight_mps * cond.clock_bias_s;
  const double el = elev_deg * kDeg;
  const double tropo_m = config_.zenith_tropo_m * TropoMapping(el);
  const double iono_l1_m =
      config_.vertical_iono_l1_m * IonoMapping(el, config_.iono_shell_height_m);
  auto [it, fresh] = tracks_.try_emplace(o.prn);
  Track& track = it->second;
  if (fresh) {
    track.acquired_gps_s = gps_s;
    std::uniform_int_distribution<std::int64_t> amb(-config_.ambiguity_span_cycles,
                                                    config_.ambiguity_span_cycles);
    for (std::size_t k = 0; k < config_.signals.size(); ++k) track.ambiguity.push_back(amb(rng_));
  }
  std::normal_distribution<double> unit(0.0, 1.0);
  const double cnr_l1 = config_.cnr_horizon_dbhz +
                        (config_.cnr_zenith_dbhz - config_.cnr_horizon_dbhz) * std::sin(el);
  const double f_l1 = config_.signals.front().frequency_hz;
  for (std::size_t k = 0; k < config_.signals.size(); ++k) {
    const SignalSpec& spec = config_.signals[k];
    SignalObservation s;
    s.msm_signal_id = spec.msm_signal_id;
    s.wavelength_m = kLight_mps / spec.frequency_hz;
    const double iono_m = iono_l1_m * (f_l1 / spec.frequency_hz) * (f_l1 / spec.frequency_hz);
    const double code_sigma_m = spec.code_noise_m / std::max(std::sin(el), 0.1);
    const double code_mp_m = Multipath(config_.code_multipath_m, o.prn, k, gps_s, el);
    const double carrier_mp_m = Multipath(config_.carrier_multipath_m, o.prn, k + 7, gps_s, el);
    s.pseudorange_m =
        o.geometric_range_m + clock_m + tropo_m + iono_m + code_mp_m + code_sigma_m * unit(rng_);
    const double phase_m = o.geometric_range_m + clock_m + tropo_m - iono_m + carrier_mp_m +
                           config_.phase_noise_m * unit(rng_);
    s.code_sigma_m = code_sigma_m;
    s.carrier_cycles = phase_m / s.wavelength_m + static_cast<double>(track.ambiguity[k]);
    s.range_rate_mps = rate_mps;
    s.lock_time_s = gps_s - track.acquired_gps_s;
    s.cnr_dbhz = cnr_l1 + spec.cnr_offset_db;
    o.signals.push_back(s);
  }
  return o;
}

std::vector<SatelliteObservation> BaseObservables::Observe(const gnss::Constellation& sky,
                                                           double gps_s,
                                                           const ObserveConditions& obs_cond) {
  if (obs_cond.sky_blocked) {
    tracks_.clear();  // every satellite lost: new ambiguities and lock times on re-acquisition
    return {};
  }
  gnss::SkyConditions cond;
  cond.elevation_mask_deg = config_.elevation_mask_deg;
  cond.sbas_enabled = false;
  cond.max_channels = 64;  // a reference receiver tracks every GPS satellite in view
  const std::vector<gnss::SatelliteView> views =
      sky.Sky(gps_s, lat_deg_, lon_deg_, height_m_, cond);
  std::map<int, std::pair<double, double>> visible;  // prn → elevation, azimuth
  for (const auto& v : views) {
    if (!v.sbas && v.elev_deg >= config_.elevation_mask_deg)
      visible[v.svid] = {v.elev_deg, v.azim_deg};
  }
  // lost satellites lose their ambiguity and lock time (a new track on re-acquisition)
  std::erase_if(tracks_, [&](const auto& kv) { return !visible.contains(kv.first); });
  std::vector<SatelliteObservation> out;
  for (std::size_t i = 0; i < sky.gps_count(); ++i) {
    const int prn = sky.GpsPositionEcef(i, gps_s).svid;
    const auto v = visible.find(prn);
    if (v == visible.end()) continue;
    out.push_back(Satellite(sky, i, gps_s, v->second.first, v->second.second, obs_cond));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.prn < b.prn; });
  return out;
}

}  // namespace hil::rtk

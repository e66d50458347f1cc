#pragma once
/// @file
/// @system
/// name: BaseObservables (GNSS observations of a receiver: the RTK base's MSM and the F9P rover's
///       RXM-RAWX, one model)
/// input: GPS time; the constellation (the same satellite positions the rover emulator uses); the
///        receiver's clock (the rover's; a base's is steered to GPS time)
/// output: per GPS satellite above the mask, per signal: pseudorange, carrier phase with an
///         integer ambiguity held while the satellite stays tracked, range rate, lock time, CNR
/// rate: on demand (each base epoch)
/// @endsystem
///
/// Model: the geometric range from the antenna to the satellite at signal emission (light-time
/// iteration, the Earth's rotation during the flight), plus a tropospheric delay (zenith delay ×
/// Black-Eisner mapping), plus an ionospheric delay (vertical L1 delay × thin-shell mapping ×
/// (f_L1/f)², on the code; the same advance on the phase), plus white noise. The base clock is
/// steered to GPS time and the synthetic satellites have no clock error, so neither appears.
/// A rover (ZED-F9P RXM-RAWX) is the same model evaluated at its antenna, with its own
/// configuration (signals, noise, multipath) and ambiguities, plus its receiver clock: bias × c
/// on code and phase, drift × c on the range rate. What the satellites and the atmosphere add is
/// the same for both receivers (the same geometry, the same zenith delays), so it cancels between
/// base and rover as in reality, up to the elevation difference of the two sites.
/// Every number below is ours (no source gives them for this synthetic sky); the reasons are
/// beside each.

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/gnss/constellation.h"

namespace hil::rtk {

/// One signal a GPS satellite broadcasts and the base tracks.
struct SignalSpec {
  int msm_signal_id = 2;  ///< RTCM MSM signal id (GPS: 2 = L1 C/A "1C", 10 = L2 P(Y) "2W")
  double frequency_hz = 1575.42e6;
  double code_noise_m = 0.3;  ///< 1σ code noise at the zenith
  double cnr_offset_db = 0;   ///< relative to the L1 C/A CNR
};

struct BaseObservablesConfig {
  /// Satellites below are not tracked: 10° is the cut-off reference stations commonly use to
  /// keep low, multipath-prone signals out of the corrections.
  double elevation_mask_deg = 10.0;
  /// Zenith tropospheric delay at the antenna: 2.3 m, the standard-atmosphere value near sea level.
  double zenith_tropo_m = 2.3;
  /// Vertical ionospheric delay on L1: 2.0 m (≈ 12 TECU), a moderate mid-latitude daytime value.
  double vertical_iono_l1_m = 2.0;
  /// Height of the ionosphere's thin shell: 350 km, the value broadcast-model users take.
  double iono_shell_height_m = 350e3;
  /// Carrier phase noise 1σ (m): 2 mm, a geodetic receiver's PLL at good CNR.
  double phase_noise_m = 0.002;
  /// Ambiguities are drawn uniformly in ±span cycles at acquisition: receivers start the phase
  /// near the code range with an arbitrary integer; ±1000 cycles keeps the phaserange within the
  /// MSM fine field (±1171 m) of the code range.
  int ambiguity_span_cycles = 1000;
  /// CNR of L1 C/A at the horizon and the zenith: 38 and 50 dBHz, a geodetic antenna's range.
  double cnr_horizon_dbhz = 38.0, cnr_zenith_dbhz = 50.0;
  /// Signals: L1 C/A and L2 P(Y) semi-codeless (every GPS satellite broadcasts both; survey bases
  /// report L2 as 2W), 6 dB weaker as semi-codeless tracking is; L2 code noise 0.5 m.
  std::vector<SignalSpec> signals = {{2, 1575.42e6, 0.3, 0.0}, {10, 1227.60e6, 0.5, -6.0}};
  /// The receiver's multipath: per satellite and signal a slow sinusoid of this amplitude at the
  /// horizon (× cos elevation) and of period `multipath_period_s` on the code and on the carrier.
  /// 0 at a base (its site and choke-ring antenna keep multipath out; ours); a rover sets it.
  double code_multipath_m = 0.0, carrier_multipath_m = 0.0;
  double multipath_period_s = 600.0;
};

/// The receiver clock at an epoch and what else limits the observations.
struct ObserveConditions {
  double clock_bias_s = 0;   ///< receiver time − GPS time (a steered base: 0)
  double clock_drift = 0;    ///< its rate (s/s)
  bool sky_blocked = false;  ///< nothing received: every track is lost
};

/// One signal's observation.
struct SignalObservation {
  int msm_signal_id = 0;
  double wavelength_m = 0;
  double pseudorange_m = 0;
  double carrier_cycles = 0;  ///< includes the held integer ambiguity
  double range_rate_mps = 0;  ///< phaserange rate (−Doppler × wavelength)
  double lock_time_s = 0;     ///< since this satellite was acquired
  double cnr_dbhz = 0;
  double code_sigma_m = 0;  ///< 1σ of the pseudorange's noise (its elevation's)
};

/// One satellite's observations at an epoch.
struct SatelliteObservation {
  int prn = 0;
  double elevation_deg = 0, azimuth_deg = 0;
  double geometric_range_m = 0;  ///< at emission, with the Earth's rotation (the truth)
  std::vector<SignalObservation> signals;
};

class BaseObservables {
 public:
  /// The antenna (its phase centre, taken at the ARP: no antenna model) at a WGS-84 position.
  BaseObservables(const BaseObservablesConfig& config, double lat_deg, double lon_deg,
                  double height_m, std::uint64_t seed);
  const Eigen::Vector3d& antenna_E_m() const { return antenna_E_m_; }
  /// Moves the antenna (a moving base): the next Observe() ranges from there. The range rate
  /// keeps the satellite's motion only (the antenna's own velocity is not in it).
  void MoveTo(double lat_deg, double lon_deg, double height_m);
  /// Observations at GPS time `gps_s` (s since the GPS epoch), sorted by PRN. Call with
  /// non-decreasing times: tracking state (ambiguities, lock times) carries over.
  std::vector<SatelliteObservation> Observe(const gnss::Constellation& sky, double gps_s,
                                            const ObserveConditions& cond = {});
  const BaseObservablesConfig& config() const { return config_; }

 private:
  struct Track {
    double acquired_gps_s = 0;
    std::vector<std::int64_t> ambiguity;  // per signal
  };
  double GeometricRange(const gnss::Constellation& sky, std::size_t index, double gps_s,
                        Eigen::Vector3d& sat_E_m) const;
  SatelliteObservation Satellite(const gnss::Constellation& sky, std::size_t index, double gps_s,
                                 double elev_deg, double azim_deg, const ObserveConditions& cond);
  double Multipath(double amplitude_m, int prn, std::size_t signal, double gps_s,
                   double elev_rad) const;

  BaseObservablesConfig config_;
  Eigen::Vector3d antenna_E_m_;
  double lat_deg_ = 0, lon_deg_ = 0, height_m_ = 0;
  std::mt19937_64 rng_;
  std::map<int, Track> tracks_;  // by PRN
};

}  // namespace hil::rtk

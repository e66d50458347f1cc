// The ZED-F9P's raw observations (RXM-RAWX): the base's observation model at the rover's antenna,
// with the rover's receiver clock.
#include <cmath>

#include "hil/firmware_emu/rtk/zed_f9p_device.h"

namespace hil::rtk {
namespace {

constexpr double kClockStep_s = 1.0e-3;  // u-blox receivers step their clock by whole ms
constexpr double kWeek_s = 604800.0;

// UBX sigId of an MSM signal id the rover tracks (GPS 1C → L1 C/A, 2L → L2 CL).
std::uint8_t UbxSigId(int msm_signal_id) {
  return msm_signal_id == 16 ? gnss::ubx::kSigGpsL2Cl : gnss::ubx::kSigGpsL1Ca;
}

}  // namespace

BaseObservablesConfig F9pRawObservables() {
  BaseObservablesConfig c;
  c.elevation_mask_deg = 5.0;
  c.phase_noise_m = 0.003;
  c.cnr_horizon_dbhz = 35.0;
  c.cnr_zenith_dbhz = 47.0;
  c.signals = {{2, 1575.42e6, 0.3, 0.0}, {16, 1227.60e6, 0.4, -3.0}};
  c.code_multipath_m = 0.5;
  c.carrier_multipath_m = 0.004;
  return c;
}

void ZedF9pDevice::ObserveRaw(const TruthSample& truth, const gnss::GpsWeekTime& gps,
                              bool sky_blocked) {
  const AntennaPosition a = AntennaAt(truth, config_.model.p_BA_B_m);
  raw_obs_.MoveTo(a.lat_deg, a.lon_deg, a.height_m);
  // the free-running clock, kept within ±0.5 ms of GPS time by whole-ms steps
  const double drift = config_.clock_drift_ppb * 1e-9;
  const double free_s = config_.clock_offset_s + drift * ToSeconds(truth.t - Time{});
  const double steps = std::round(free_s / kClockStep_s);
  ObserveConditions cond;
  cond.clock_bias_s = free_s - steps * kClockStep_s;
  cond.clock_drift = drift;
  cond.sky_blocked = sky_blocked;
  gnss::ubx::RawxEpoch& r = rawx_;
  r.clk_reset = steps != clock_steps_;
  clock_steps_ = steps;
  const double gps_s = static_cast<double>(gps.week) * kWeek_s + gps.tow_s();
  const std::vector<SatelliteObservation> obs = raw_obs_.Observe(constellation_, gps_s, cond);
  double tow_s = gps.tow_s() + cond.clock_bias_s;
  r.week = static_cast<std::uint16_t>(gps.week);
  if (tow_s < 0) tow_s += kWeek_s, --r.week;
  if (tow_s >= kWeek_s) tow_s -= kWeek_s, ++r.week;
  r.rcv_tow_s = tow_s;
  r.leap_s = last_.nav.leap_s;
  r.leap_valid = true;
  r.meas.clear();
  for (const SatelliteObservation& o : obs) {
    for (const SignalObservation& g : o.signals) {
      gnss::ubx::RawxMeasurement m;
      m.pr_m = g.pseudorange_m;
      m.cp_cycles = g.carrier_cycles;
      m.do_hz = -g.range_rate_mps / g.wavelength_m;
      m.sv_id = static_cast<std::uint8_t>(o.prn);
      m.sig_id = UbxSigId(g.msm_signal_id);
      m.locktime_ms = g.lock_time_s * 1000.0;
      m.cno_dbhz = g.cnr_dbhz;
      m.pr_sigma_m = g.code_sigma_m;
      m.cp_sigma_cycles = config_.raw.phase_noise_m / g.wavelength_m;
      // the Doppler's noise: the phase noise differenced over the 1 s of a PLL's loop (ours)
      m.do_sigma_hz = std::sqrt(2.0) * m.cp_sigma_cycles;
      r.meas.push_back(m);
    }
  }
}

}  // namespace hil::rtk

#include "hil/firmware_emu/rtk/rtk_base_device.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

namespace hil::rtk {

RtkBaseDevice::RtkBaseDevice(const RtkBaseConfig& config, std::uint64_t seed)
    : config_(config),
      constellation_(seed),
      observables_(config.observables, config.lat_deg, config.lon_deg, config.height_m, seed),
      radio_(config.radio, seed) {
  if (config_.station_message != 1005 && config_.station_message != 1006)
    throw std::invalid_argument("rtk_base station_message must be 1005 or 1006");
  if (!(config_.obs_rate_hz > 0 && config_.obs_rate_hz <= 20))
    throw std::invalid_argument("rtk_base obs_rate_hz must be in (0, 20]");
  next_epoch_ = NextGridEpoch(TimeFromNs(-1));
  next_station_ = next_epoch_;
}

Time RtkBaseDevice::NextGridEpoch(Time after) const {
  // epochs on the GPS-second grid of the observation period (GPS − UTC is whole seconds)
  return hil::NextGridEpoch(after, PeriodFromHz(config_.obs_rate_hz), config_.start_utc);
}

rtcm3::StationInfo RtkBaseDevice::station() const {
  rtcm3::StationInfo s;
  s.station_id = config_.station_id;
  s.arp_E_m = observables_.antenna_E_m();
  s.antenna_height_m = config_.antenna_height_m;
  return s;
}

rtcm3::MsmEpoch MsmEpochOf(const std::vector<SatelliteObservation>& obs, int station_id,
                           std::uint32_t tow_ms) {
  rtcm3::MsmEpoch e;
  e.station_id = station_id;
  e.epoch_time_ms = tow_ms;
  e.clock_steering = 1;  // the base clock is steered to GPS time (no clock term in the ranges)
  for (const SatelliteObservation& o : obs) {
    rtcm3::MsmSatellite s;
    s.id = o.prn;
    for (const SignalObservation& g : o.signals) {
      rtcm3::MsmSignal m;
      m.signal_id = g.msm_signal_id;
      m.pseudorange_m = g.pseudorange_m;
      m.phaserange_m = g.carrier_cycles * g.wavelength_m;
      m.phaserange_rate_mps = g.range_rate_mps;
      m.lock_time_s = g.lock_time_s;
      m.cnr_dbhz = g.cnr_dbhz;
      s.signals.push_back(m);
    }
    std::sort(s.signals.begin(), s.signals.end(),
              [](const auto& a, const auto& b) { return a.signal_id < b.signal_id; });
    e.satellites.push_back(s);
  }
  // 64 cells hold 32 satellites of two signals: more than the 30 GPS orbits of the constellation
  return e;
}

std::vector<SerialMessage> RtkBaseDevice::EncodeEpoch(Time t) {
  const gnss::GpsWeekTime gps = gnss::GpsFrom(UtcAt(config_.start_utc, t));
  const double gps_s = static_cast<double>(gps.week) * 604800.0 + gps.tow_s();
  std::vector<SerialMessage> out;
  if (t >= next_station_) {
    const rtcm3::StationInfo s = station();
    const std::string body =
        config_.station_message == 1005 ? rtcm3::Encode1005(s) : rtcm3::Encode1006(s);
    out.push_back({t, 0, rtcm3::Frame(body), "RTCM3-" + std::to_string(config_.station_message)});
    next_station_ = t + config_.station_interval;
  }
  last_msm_ =
      MsmEpochOf(observables_.Observe(constellation_, gps_s), config_.station_id, gps.itow_ms());
  const int number = 1070 + static_cast<int>(config_.msm);
  out.push_back({t, 0, rtcm3::Frame(rtcm3::EncodeGpsMsm(last_msm_, config_.msm)),
                 "RTCM3-" + std::to_string(number)});
  return out;
}

void RtkBaseDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  next_epoch_ = NextGridEpoch(t);
  std::vector<SerialMessage> frames = EncodeEpoch(t);
  std::size_t bytes = 0;
  for (const SerialMessage& m : frames) bytes += m.bytes.size();
  ++stats_.epochs;
  stats_.frames += frames.size();
  stats_.bytes += bytes;
  const std::optional<Time> arrival = radio_.Deliver(t + config_.output_lag, bytes);
  if (!arrival) {
    ++stats_.packets_lost;
    stats_.frames_lost += frames.size();
    return;
  }
  for (SerialMessage& m : frames) {
    m.t_ready = *arrival;
    out.serial.push_back(std::move(m));
  }
}

}  // namespace hil::rtk

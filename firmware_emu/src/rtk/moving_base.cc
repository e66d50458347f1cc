#include "hil/firmware_emu/rtk/moving_base.h"

#include <cmath>
#include <numbers>
#include <string>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_moving_base.h"
#include "hil/firmware_emu/rtk/rtk_base_device.h"

namespace hil::rtk {

AntennaPosition AntennaAt(const TruthSample& truth, const Eigen::Vector3d& p_BA_B_m) {
  const Eigen::Vector3d d_N = truth.q_NB * p_BA_B_m;  // ENU
  const double lat = truth.lat_deg * std::numbers::pi / 180.0;
  const double s = std::sin(lat);
  const double w = std::sqrt(1.0 - gnss::kWgs84E2 * s * s);
  const double rn_m = gnss::kWgs84A_m / w + truth.height_m;
  const double rm_m = gnss::kWgs84A_m * (1.0 - gnss::kWgs84E2) / (w * w * w) + truth.height_m;
  AntennaPosition a;
  a.lat_deg = truth.lat_deg + d_N.y() / rm_m * 180.0 / std::numbers::pi;
  a.lon_deg = truth.lon_deg + d_N.x() / (rn_m * std::cos(lat)) * 180.0 / std::numbers::pi;
  a.height_m = truth.height_m + d_N.z();
  a.p_E_m = gnss::EcefFromGeodetic(a.lat_deg, a.lon_deg, a.height_m);
  return a;
}

MovingBase::MovingBase(const MovingBaseConfig& config, UnixTime start_utc, std::uint64_t seed)
    : config_(config),
      start_utc_(start_utc),
      constellation_(seed),
      observables_(config.observables, 0, 0, 0, seed ^ 0x4D42ULL) {}

std::vector<SerialMessage> MovingBase::Epoch(const TruthSample& truth) {
  const AntennaPosition a = AntennaAt(truth, config_.p_BA_B_m);
  observables_.MoveTo(a.lat_deg, a.lon_deg, a.height_m);
  const gnss::GpsWeekTime gps = gnss::GpsFrom(UtcAt(start_utc_, truth.t));
  const double gps_s = static_cast<double>(gps.week) * 604800.0 + gps.tow_s();
  const rtcm3::MovingBasePvt pvt{config_.station_id, gps.itow_ms(), a.p_E_m};
  const rtcm3::MsmEpoch msm =
      MsmEpochOf(observables_.Observe(constellation_, gps_s), config_.station_id, gps.itow_ms());
  const Time ready = truth.t + config_.output_lag;
  const int number = 1070 + static_cast<int>(config_.msm);
  return {{ready, 0, rtcm3::Frame(rtcm3::Encode4072Pvt(pvt)), "RTCM3-4072.0"},
          {ready, 0, rtcm3::Frame(rtcm3::EncodeGpsMsm(msm, config_.msm)),
           "RTCM3-" + std::to_string(number)}};
}

}  // namespace hil::rtk

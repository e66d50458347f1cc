#pragma once
/// @file
/// @system
/// name: RtkBaseDevice (an RTK reference station and its correction radio)
/// input: emulated time (the base is surveyed and still: the truth is not read)
/// output: RTCM 3.3 frames on one serial port, through a RadioLink: a GPS MSM (1074 or 1077) each
///         observation epoch and the station message (1005 or 1006) every `station_interval`
/// rate: `obs_rate_hz` (default 1 Hz); station message every 10 s by default
/// @endsystem
///
/// Layers: Constellation (the rover's sky) → BaseObservables → MsmEpoch / StationInfo →
/// rtcm3_msm / rtcm3_station bodies → rtcm3_frame → one radio packet per epoch → SerialMessages
/// at the packet's arrival time (the port's UART queue then times the bytes at `baud`).
/// The constellation has GPS and SBAS only, so the base sends no GLONASS MSM and no 1230
/// (GLONASS code-phase biases): a GPS-only base sends neither.

#include <cstdint>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/rtk/base_observables.h"
#include "hil/firmware_emu/rtk/radio_link.h"
#include "hil/firmware_emu/rtk/rtcm3_msm.h"
#include "hil/firmware_emu/rtk/rtcm3_station.h"
#include "hil/firmware_emu/unix_time.h"

namespace hil::rtk {

struct RtkBaseConfig {
  std::string name = "base0";
  int station_id = 1;               ///< DF003
  double lat_deg = 0, lon_deg = 0;  ///< surveyed ARP, WGS-84
  double height_m = 0;              ///< ellipsoidal height of the ARP
  double antenna_height_m = 0;      ///< ARP above the marker (1006 DF028)
  rtcm3::MsmKind msm = rtcm3::MsmKind::kMsm7;
  int station_message = 1006;  ///< 1005 or 1006
  double obs_rate_hz = 1.0;
  Duration station_interval = std::chrono::seconds(10);
  /// Epoch → packet handed to the radio: 30 ms of receiver computation (ours).
  Duration output_lag = std::chrono::milliseconds(30);
  /// Radio modem → rover UART line rate: 38400 bit/s, a common RTK radio port setting (ours).
  int baud = 38400;
  UnixTime start_utc{};  ///< UTC of scenario time 0
  BaseObservablesConfig observables;
  RadioLinkConfig radio;
};

/// What the base sent and the radio delivered.
struct RtkBaseStatistics {
  std::uint64_t epochs = 0, frames = 0, bytes = 0;
  std::uint64_t packets_lost = 0, frames_lost = 0;
};

/// The MSM epoch of a base's observations (clock steered to GPS time; signals by MSM id).
rtcm3::MsmEpoch MsmEpochOf(const std::vector<SatelliteObservation>& obs, int station_id,
                           std::uint32_t tow_ms);

class RtkBaseDevice final : public Device {
 public:
  RtkBaseDevice(const RtkBaseConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_epoch_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  int baud(int port) const override { return (void)port, config_.baud; }

  /// The frames of the epoch at `t` (what the base sends, before the radio): station message
  /// first when due, then the MSM. Advances the tracking state (call with increasing times).
  std::vector<SerialMessage> EncodeEpoch(Time t);
  /// The station message contents (what 1005/1006 carry).
  rtcm3::StationInfo station() const;
  /// The MSM epoch of the last EncodeEpoch (the values before quantisation).
  const rtcm3::MsmEpoch& last_msm() const { return last_msm_; }
  const RtkBaseStatistics& rtk_statistics() const { return stats_; }

 private:
  Time NextGridEpoch(Time after) const;

  RtkBaseConfig config_;
  gnss::Constellation constellation_;
  BaseObservables observables_;
  RadioLink radio_;
  Time next_epoch_{};
  Time next_station_{};
  rtcm3::MsmEpoch last_msm_;
  RtkBaseStatistics stats_;
};

}  // namespace hil::rtk

#pragma once
// The base the rtk tests share: surveyed at the default scenario's origin (Karaj), the default
// scenario's start time, and the stream it sends without a radio.
#include <string>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/rtk/rtk_base_device.h"

namespace hil::rtk::test {

inline RtkBaseConfig KarajBase(rtcm3::MsmKind msm) {
  RtkBaseConfig c;
  c.station_id = 1234;
  c.lat_deg = 35.4796096;
  c.lon_deg = 50.5979765;
  c.height_m = 1312.0;
  c.antenna_height_m = 1.5;
  c.msm = msm;
  c.start_utc = gnss::ParseIsoUtc("2026-06-10T08:00:00Z");
  return c;
}

/// The bytes the base sends over `seconds` epochs at 1 Hz (no radio).
inline std::string BaseStream(const RtkBaseConfig& config, int seconds, std::uint64_t seed) {
  RtkBaseDevice base(config, seed);
  std::string s;
  for (int k = 0; k < seconds; ++k) {
    for (const SerialMessage& m : base.EncodeEpoch(TimeFromNs(k * 1000000000LL))) s += m.bytes;
  }
  return s;
}

}  // namespace hil::rtk::test

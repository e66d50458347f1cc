#pragma once
// The rover the zed_f9p tests share: still at the rtk base fixture's site (Karaj), its base 2 km
// away (offset 1200 m east, 1600 m north) on a 960 B/s radio, run event by event.
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/firmware_emu/rtk/zed_f9p_device.h"

#include "rtk_base_fixture.h"

namespace hil::rtk::test {

inline constexpr double kRoverLat_deg = 35.4796096, kRoverLon_deg = 50.5979765;
inline constexpr double kRoverHeight_m = 1312.0;

/// The rover with its radio base 2 km away (1200 m east, 1600 m north) and the radio's outages.
inline ZedF9pConfig RoverWithRadio(std::vector<RadioOutage> outages = {}) {
  ZedF9pConfig c;
  c.start_utc = gnss::ParseIsoUtc("2026-06-10T08:00:00Z");
  RtkBaseConfig b = KarajBase(rtcm3::MsmKind::kMsm7);
  // the radii of curvature of the ellipsoid at the site (meridian M, prime vertical N)
  const double rad = 3.141592653589793 / 180.0, s = std::sin(kRoverLat_deg * rad);
  const double w = std::sqrt(1.0 - gnss::kWgs84E2 * s * s);
  const double m_m = gnss::kWgs84A_m * (1.0 - gnss::kWgs84E2) / (w * w * w) + kRoverHeight_m;
  const double n_m = gnss::kWgs84A_m / w + kRoverHeight_m;
  b.lat_deg += 1600.0 / m_m / rad;
  b.lon_deg += 1200.0 / (n_m * std::cos(kRoverLat_deg * rad)) / rad;
  b.radio.outages = std::move(outages);
  c.radio_base = b;
  c.radio_base_seed = 7;
  return c;
}

inline TruthSample StillTruth(Time t) {
  TruthSample s;
  s.t = t;
  s.lat_deg = kRoverLat_deg;
  s.lon_deg = kRoverLon_deg;
  s.height_m = kRoverHeight_m;
  s.p_EB_E_m = gnss::EcefFromGeodetic(kRoverLat_deg, kRoverLon_deg, kRoverHeight_m);
  return s;
}

/// Runs the device's events up to `end` (exclusive); returns what it sent.
inline std::vector<SerialMessage> RunUntil(ZedF9pDevice& dev, Time end) {
  std::vector<SerialMessage> sent;
  DeviceOutput out;
  while (dev.next_event_time() < end) {
    dev.OnEvent(StillTruth(dev.next_event_time()), out);
    for (auto& m : out.serial) sent.push_back(std::move(m));
    out.clear();
  }
  return sent;
}

}  // namespace hil::rtk::test

// The scenario's `rtk_base:` section: an RTK reference station (firmware_emu/rtk) and its
// correction radio, on its own pty. Format in vectors/scenarios/README.md; the message layouts in
// vectors/rtcm3/README.md.
#include <cmath>

#include "hil/truth/local_frame.h"

#include "rtk_base.h"

namespace hil::harness {
namespace {

constexpr double kMaxBaseline_m = 200e3;  // RTK beyond 200 km is not RTK

// The surveyed ARP: `position: {lat_deg, lon_deg, height_m}`, or `offset_enu_m: [e, n, u]` from
// the scenario origin (default [0, 0, 0]).
void ReadPosition(const YamlReader& r, const truth::Geodetic& origin, rtk::RtkBaseConfig& c) {
  if (r.Has("position") && r.Has("offset_enu_m"))
    r.Fail("position", "give either position or offset_enu_m, not both");
  if (auto p = r.OptionalChild("position")) {
    p->CheckKeys({"lat_deg", "lon_deg", "height_m"});
    c.lat_deg = p->DoubleIn("lat_deg", 0, -90, 90);
    c.lon_deg = p->DoubleIn("lon_deg", 0, -180, 180);
    c.height_m = p->DoubleIn("height_m", 0, -500, 9000);
    return;
  }
  const std::vector<double> v = r.Doubles("offset_enu_m", 3, {0, 0, 0});
  for (const double x : v) {
    if (!(std::abs(x) <= kMaxBaseline_m))
      r.Fail("offset_enu_m", "each component must be within 200 km of the origin");
  }
  const truth::Geodetic g = truth::LocalFrame(origin).ToGeodetic({v[0], v[1], v[2]});
  c.lat_deg = g.lat_deg;
  c.lon_deg = g.lon_deg;
  c.height_m = g.height_m;
}

void ReadRadio(const YamlReader& r, double duration_s, rtk::RadioLinkConfig& c) {
  r.CheckKeys({"bytes_per_s", "latency_s", "loss_probability", "outages"});
  c.bytes_per_s = r.DoubleIn("bytes_per_s", c.bytes_per_s, 10, 1e6);
  c.latency = DurationFromSeconds(r.DoubleIn("latency_s", ToSeconds(c.latency), 0, 10));
  c.loss_probability = r.DoubleIn("loss_probability", c.loss_probability, 0, 1);
  if (auto o = r.OptionalChild("outages")) {
    for (const YamlReader& e : o->Elements()) {
      e.CheckKeys({"start_s", "end_s"});
      const double start = e.DoubleIn("start_s", 0, 0, duration_s);
      const double end = e.DoubleIn("end_s", duration_s, 0, duration_s);
      if (end <= start) e.Fail("end_s", "must be after start_s");
      c.outages.push_back({TimeFromSeconds(start), TimeFromSeconds(end)});
    }
  }
}

void ReadObservables(const YamlReader& r, rtk::BaseObservablesConfig& c) {
  r.CheckKeys({"elevation_mask_deg", "zenith_tropo_m", "vertical_iono_l1_m", "phase_noise_m"});
  c.elevation_mask_deg = r.DoubleIn("elevation_mask_deg", c.elevation_mask_deg, 0, 60);
  c.zenith_tropo_m = r.DoubleIn("zenith_tropo_m", c.zenith_tropo_m, 0, 5);
  c.vertical_iono_l1_m = r.DoubleIn("vertical_iono_l1_m", c.vertical_iono_l1_m, 0, 50);
  c.phase_noise_m = r.DoubleIn("phase_noise_m", c.phase_noise_m, 0, 0.05);
}

}  // namespace

void ReadRtkBaseSpec(const YamlReader& root, Scenario& s) {
  const auto r = root.OptionalChild("rtk_base");
  if (!r) return;
  r->CheckKeys({"link", "station_id", "position", "offset_enu_m", "antenna_height_m", "msm",
                "station_message", "obs_rate_hz", "station_interval_s", "output_lag_s", "baud",
                "tx_buffer_bytes", "radio", "observables"});
  RtkBaseDeviceSpec& b = s.rtk_base;
  rtk::RtkBaseConfig& c = b.config;
  b.enabled = true;
  b.link = r->String("link", b.link);
  if (b.link.empty() || b.link.find('/') != std::string::npos)
    r->Fail("link", "must be a plain file name such as ttyRTCM");
  c.start_unix_ns = s.start_unix_ns;
  c.station_id = static_cast<int>(r->Int("station_id", c.station_id, 0, 4095));
  ReadPosition(*r, s.truth.origin, c);
  c.antenna_height_m = r->DoubleIn("antenna_height_m", c.antenna_height_m, 0, 6.5535);
  const std::int64_t msm = r->Int("msm", 7, 4, 7);
  if (msm != 4 && msm != 7) r->Fail("msm", "must be 4 (MSM4) or 7 (MSM7)");
  c.msm = msm == 4 ? rtcm3::MsmKind::kMsm4 : rtcm3::MsmKind::kMsm7;
  c.station_message = static_cast<int>(r->Int("station_message", 1006, 1005, 1006));
  c.obs_rate_hz = r->DoubleIn("obs_rate_hz", c.obs_rate_hz, 0.1, 20);
  c.station_interval = DurationFromSeconds(
      r->DoubleIn("station_interval_s", ToSeconds(c.station_interval), 1, 3600));
  c.output_lag = DurationFromSeconds(r->DoubleIn("output_lag_s", ToSeconds(c.output_lag), 0, 1));
  c.baud = static_cast<int>(r->Int("baud", c.baud, 1200, 921600));
  b.tx_buffer_bytes = static_cast<std::size_t>(
      r->Int("tx_buffer_bytes", static_cast<std::int64_t>(b.tx_buffer_bytes), 256, 1 << 20));
  if (auto radio = r->OptionalChild("radio")) ReadRadio(*radio, s.duration_s, c.radio);
  if (auto o = r->OptionalChild("observables")) ReadObservables(*o, c.observables);
}

}  // namespace hil::harness

// The scenario's `rtk_base:` section: an RTK reference station (firmware_emu/rtk) and its
// correction radio, on its own pty. Its keys' table is below (docs/scenario_reference.md); the
// message layouts in vectors/rtcm3/README.md.
#include <cmath>

#include "hil/truth/local_frame.h"

#include "rtk_base.h"

namespace hil::harness {
namespace rtk_base_keys {  // named: the unity build joins the devices' files

using enum KeyType;

// Every default is this project's choice (no source gives them for a synthetic sky): the reasons
// are in firmware_emu/include/hil/firmware_emu/rtk/.
inline constexpr std::string_view kOurs = "ours (the code cites no source)";

inline constexpr ScenarioKey kRtkBase[] = {
    {"link", kString, "", "ttyRTCM", 0, 0, "its pty in the run folder (a plain file name)"},
    {"station_id", kInteger, "", "1", 0, 4095, "reference station id, DF003 of every message"},
    {"position", kMapping, "", "offset_enu_m", 0, 0,
     "the surveyed antenna reference point (rtk_base.position); not with offset_enu_m"},
    {"offset_enu_m", kPoint, "m", "[0, 0, 0]", 0, 0,
     "or the ARP from the scenario origin [east, north, up], each within 200 km"},
    {"antenna_height_m", kNumber, "m", "0", 0, 6.5535, "ARP above the marker (1006 DF028)"},
    {"msm", kInteger, "", "7", 4, 7, "4 (message 1074) or 7 (1077)", kNoChoices, "4 or 7"},
    {"station_message", kInteger, "", "1006", 1005, 1006, "the station message: 1005 or 1006"},
    {"obs_rate_hz", kNumber, "Hz", "1", 0.1, 20, "MSM epochs, on the GPS-second grid", kNoChoices,
     kAnyRange, kOurs},
    {"station_interval_s", kNumber, "s", "10", 1, 3600,
     "interval of the station message (the first at the first epoch)", kNoChoices, kAnyRange,
     kOurs},
    {"output_lag_s", kNumber, "s", "0.03", 0, 1, "epoch to the packet handed to the radio",
     kNoChoices, kAnyRange, "ours: 30 ms of receiver computation (rtk_base_device.h)"},
    {"baud", kInteger, "Bd", "38400", 1200, 921600, "the radio modem's UART to the rover",
     kNoChoices, kAnyRange, "ours: a common RTK radio port setting (rtk_base_device.h)"},
    {"tx_buffer_bytes", kInteger, "B", "4096", 256, 1 << 20, "its UART's transmit buffer",
     kNoChoices, kAnyRange, kOurs},
    {"radio", kMapping, "", "the defaults below", 0, 0, "the correction radio (rtk_base.radio)"},
    {"observables", kMapping, "", "the defaults below", 0, 0,
     "the base's observation model (rtk_base.observables)"},
};

inline constexpr ScenarioKey kPosition[] = {
    {"lat_deg", kNumber, "deg", "0", -90, 90, "latitude of the ARP (WGS-84)"},
    {"lon_deg", kNumber, "deg", "0", -180, 180, "its longitude, east positive"},
    {"height_m", kNumber, "m", "0", -500, 9000,
     "its ellipsoidal height (not above mean sea level)"},
};

inline constexpr ScenarioKey kRadio[] = {
    {"bytes_per_s", kNumber, "B/s", "960", 10, 1e6,
     "air throughput; packets queue behind each other", kNoChoices, kAnyRange,
     "ours: a 9600 bit/s air rate with 8N1-like overhead, the lowest setting of the common "
     "430–470 MHz modems (radio_link.h)"},
    {"latency_s", kNumber, "s", "0.05", 0, 10,
     "from a packet's last byte on air to its first byte at the rover's UART", kNoChoices,
     kAnyRange, "ours: modem buffering and forward error correction (radio_link.h)"},
    {"loss_probability", kNumber, "", "0", 0, 1,
     "each epoch's packet lost with this probability (seeded)"},
    {"outages", kList, "", "none", 0, 0,
     "intervals in which nothing arrives (rtk_base.radio.outages[])"},
};

inline constexpr ScenarioKey kOutage[] = {
    {"start_s", kNumber, "s", "0", 0, 7 * 86400, "the outage's start", kNoChoices,
     "[0, duration_s]"},
    {"end_s", kNumber, "s", "duration_s", 0, 7 * 86400, "its end (after start_s)", kNoChoices,
     "[0, duration_s]"},
};

inline constexpr ScenarioKey kObservables[] = {
    {"elevation_mask_deg", kNumber, "deg", "10", 0, 60, "satellites below are not tracked",
     kNoChoices, kAnyRange,
     "ours: the cut-off reference stations commonly use against low, multipath-prone signals "
     "(base_observables.h)"},
    {"zenith_tropo_m", kNumber, "m", "2.3", 0, 5, "zenith tropospheric delay at the antenna",
     kNoChoices, kAnyRange, "the standard-atmosphere value near sea level (base_observables.h)"},
    {"vertical_iono_l1_m", kNumber, "m", "2", 0, 50, "vertical ionospheric delay on L1", kNoChoices,
     kAnyRange, "≈ 12 TECU, a moderate mid-latitude daytime value (base_observables.h)"},
    {"phase_noise_m", kNumber, "m", "0.002", 0, 0.05, "carrier phase noise (1σ)", kNoChoices,
     kAnyRange, "a geodetic receiver's PLL at good CNR (base_observables.h)"},
};

}  // namespace rtk_base_keys

namespace {

using rtk_base_keys::kObservables;
using rtk_base_keys::kOutage;
using rtk_base_keys::kPosition;
using rtk_base_keys::kRadio;
using rtk_base_keys::kRtkBase;

constexpr double kMaxBaseline_m = 200e3;  // RTK beyond 200 km is not RTK

// The surveyed ARP: `position: {lat_deg, lon_deg, height_m}`, or `offset_enu_m: [e, n, u]` from
// the scenario origin (default [0, 0, 0]).
void ReadPosition(const KeyedReader<kRtkBase>& r, const truth::Geodetic& origin,
                  rtk::RtkBaseConfig& c) {
  if (r.Has("position") && r.Has("offset_enu_m"))
    r.Fail("position", "give either position or offset_enu_m, not both");
  if (auto y = r.OptionalChild("position")) {
    const KeyedReader<kPosition> p(*y);
    p.CheckKeys();
    c.lat_deg = p.Number("lat_deg", 0);
    c.lon_deg = p.Number("lon_deg", 0);
    c.height_m = p.Number("height_m", 0);
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

void ReadRadio(const YamlReader& y, double duration_s, rtk::RadioLinkConfig& c) {
  const KeyedReader<kRadio> r(y);
  r.CheckKeys();
  c.bytes_per_s = r.Number("bytes_per_s", c.bytes_per_s);
  c.latency = DurationFromSeconds(r.Number("latency_s", ToSeconds(c.latency)));
  c.loss_probability = r.Number("loss_probability", c.loss_probability);
  if (auto o = r.OptionalChild("outages")) {
    for (const YamlReader& item : o->Elements()) {
      const KeyedReader<kOutage> e(item);
      e.CheckKeys();
      const double start = e.NumberIn("start_s", 0, 0, duration_s);
      const double end = e.NumberIn("end_s", duration_s, 0, duration_s);
      if (end <= start) e.Fail("end_s", "must be after start_s");
      c.outages.push_back({TimeFromSeconds(start), TimeFromSeconds(end)});
    }
  }
}

void ReadObservables(const YamlReader& y, rtk::BaseObservablesConfig& c) {
  const KeyedReader<kObservables> r(y);
  r.CheckKeys();
  c.elevation_mask_deg = r.Number("elevation_mask_deg", c.elevation_mask_deg);
  c.zenith_tropo_m = r.Number("zenith_tropo_m", c.zenith_tropo_m);
  c.vertical_iono_l1_m = r.Number("vertical_iono_l1_m", c.vertical_iono_l1_m);
  c.phase_noise_m = r.Number("phase_noise_m", c.phase_noise_m);
}

}  // namespace

void ReadRtkBaseSpec(const YamlReader& root, Scenario& s) {
  const auto y = root.OptionalChild("rtk_base");
  if (!y) return;
  const KeyedReader<kRtkBase> r(*y);
  r.CheckKeys();
  RtkBaseDeviceSpec& b = s.rtk_base;
  rtk::RtkBaseConfig& c = b.config;
  b.enabled = true;
  b.link = r.String("link", b.link);
  if (b.link.empty() || b.link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as ttyRTCM");
  c.start_utc = s.start_utc;
  c.station_id = static_cast<int>(r.Integer("station_id", c.station_id));
  ReadPosition(r, s.truth.origin, c);
  c.antenna_height_m = r.Number("antenna_height_m", c.antenna_height_m);
  const std::int64_t msm = r.Integer("msm", 7);
  if (msm != 4 && msm != 7) r.Fail("msm", "must be 4 (MSM4) or 7 (MSM7)");
  c.msm = msm == 4 ? rtcm3::MsmKind::kMsm4 : rtcm3::MsmKind::kMsm7;
  c.station_message = static_cast<int>(r.Integer("station_message", 1006));
  c.obs_rate_hz = r.Number("obs_rate_hz", c.obs_rate_hz);
  c.station_interval =
      DurationFromSeconds(r.Number("station_interval_s", ToSeconds(c.station_interval)));
  c.output_lag = DurationFromSeconds(r.Number("output_lag_s", ToSeconds(c.output_lag)));
  c.baud = static_cast<int>(r.Integer("baud", c.baud));
  b.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(b.tx_buffer_bytes)));
  if (auto radio = r.OptionalChild("radio")) ReadRadio(*radio, s.duration_s, c.radio);
  if (auto o = r.OptionalChild("observables")) ReadObservables(*o, c.observables);
}

extern const KeySection kRtkBaseSection{
    "rtk_base",
    "an RTK reference station sending RTCM 3.3 (GPS MSM4 or MSM7, 1005 or 1006) on its own pty, as "
    "a radio modem's UART at the rover delivers it (vectors/rtcm3/README.md)",
    rtk_base_keys::kRtkBase};
extern const KeySection kRtkBasePositionSection{
    "rtk_base.position", "the surveyed antenna reference point (ARP)", rtk_base_keys::kPosition};
extern const KeySection kRtkBaseRadioSection{"rtk_base.radio", "the correction radio",
                                             rtk_base_keys::kRadio};
extern const KeySection kRtkBaseOutageSection{
    "rtk_base.radio.outages[]", "one radio outage (scenario time)", rtk_base_keys::kOutage};
extern const KeySection kRtkBaseObservablesSection{
    "rtk_base.observables", "the base's mask and observation model", rtk_base_keys::kObservables};

}  // namespace hil::harness

// The `gnss` section of a scenario (owner: GNSS emulator). Format:
//
// gnss:
//   profile: neo-5m            # or rtk (10 Hz, 115200 baud, GGA quality 5 then 4, cm errors)
//   baud: 9600                 # default: the profile's
//   link: ttyGPS               # first receiver's link; further ones get ttyGPS1, ttyGPS2, ...
//   rate_hz: 1                 # default: the profile's; at most its maximum (4 Hz NEO-5M, 20 Hz
//   rtk) output_lag_s: 0.1 tx_buffer_bytes: 1024 start: hot                 # cold | warm | hot:
//   time to first fix of the power-up antenna_lever_arm_m: [x, y, z]          # body FLU, single
//   receiver count: 3                   # receivers on a horizontal circle around the lever arm ...
//   array_radius_m: 3.0        # ... of this radius (first one forward, then every 360/count deg)
//   receivers:                 # or list them (overrides count)
//     - {link: ttyGPS, antenna_lever_arm_m: [0, 0, 1]}
//   errors: {horizontal_sigma_m, vertical_sigma_m, correlation_time_s, velocity_sigma_mps,
//            common_fraction}
//   geoid: ublox5              # geoid height N at each fix: ublox5 (EGM96 on the receiver's 10°
//                              # table, the default) or egm96 (the 15' grid)
//   geoid_separation_m: -20.0  # or a fixed N instead
//   multipath: {track_min_dbhz, nav_min_dbhz, correlator_spacing_chip}   # with obstructions:
//   rtk: {time_to_fix_s, ..., wrong_fix_probability}   # rough RTK (gnss_rough_spec.cc)
//   faults:                    # the receiver's own fault timeline (scenario seconds)
//     - {kind: outage, start_s: 30, end_s: 45}
//     - {kind: obstruction, start_s: 60, end_s: 70, elevation_deg: 40}
//     - {kind: step, start_s: 80, end_s: 90, offset_m: [2, 0, 0]}     # ENU
//     - {kind: multipath, start_s: 100, end_s: 110, sigma_m: 3}
//     - {kind: data_gap, start_s: 120, end_s: 130}   # output removed, receiver keeps its fix
#include <cmath>
#include <numbers>

#include "gnss_receiver.h"

namespace hil::harness {
namespace {

gnss::GnssFault ReadFault(const YamlReader& f) {
  f.CheckKeys({"kind", "start_s", "end_s", "elevation_deg", "offset_m", "sigma_m"});
  gnss::GnssFault g;
  const std::string kind =
      f.Choice("kind", "outage", {"outage", "obstruction", "step", "multipath", "data_gap"});
  g.kind = kind == "outage"        ? gnss::GnssFault::Kind::kOutage
           : kind == "obstruction" ? gnss::GnssFault::Kind::kObstruction
           : kind == "step"        ? gnss::GnssFault::Kind::kStep
           : kind == "multipath"   ? gnss::GnssFault::Kind::kMultipath
                                   : gnss::GnssFault::Kind::kDataGap;
  const double start_s = f.DoubleIn("start_s", 0, 0, 1e7);
  const double end_s = f.DoubleIn("end_s", start_s, 0, 1e7);
  if (end_s <= start_s) f.Fail("end_s", "must be after start_s");
  g.start = TimeFromSeconds(start_s);
  g.end = TimeFromSeconds(end_s);
  g.elevation_deg = f.DoubleIn("elevation_deg", g.elevation_deg, 0, 90);
  const auto off = f.Doubles("offset_m", 3, {0, 0, 0});
  g.offset_N_m = Eigen::Vector3d(off[0], off[1], off[2]);
  g.sigma_m = f.DoubleIn("sigma_m", g.sigma_m, 0, 1000);
  return g;
}

void ReadGnss(const YamlReader& r, GnssDeviceSpec& g) {
  r.CheckKeys({"profile", "baud", "link", "rate_hz", "output_lag_s", "tx_buffer_bytes", "errors",
               "antenna_lever_arm_m", "start", "count", "array_radius_m", "receivers", "faults",
               "geoid", "geoid_separation_m", "multipath", "rtk"});
  g.profile = r.Choice("profile", g.profile, {"neo-5m", "rtk"});
  const gnss::ReceiverProfile profile = gnss::ProfileByName(g.profile);
  g.baud = static_cast<int>(r.Int("baud", profile.baud, 1200, 921600));
  g.link = r.String("link", g.link);
  if (g.link.empty() || g.link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as ttyGPS");
  g.rate_hz = r.DoubleIn("rate_hz", profile.rate_hz, 0.1, 20);
  if (g.rate_hz > profile.max_rate_hz) {
    r.Fail("rate_hz", "above the " + g.profile + " maximum of " +
                          std::to_string(static_cast<int>(profile.max_rate_hz)) + " Hz");
  }
  g.output_lag_s = r.DoubleIn("output_lag_s", g.output_lag_s, 0, 0.9);
  g.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 1024, 64, 1 << 20));
  const std::string start = r.Choice("start", "hot", {"cold", "warm", "hot"});
  g.start = start == "cold"   ? gnss::StartKind::kCold
            : start == "warm" ? gnss::StartKind::kWarm
                              : gnss::StartKind::kHot;
  const auto lever = r.Doubles("antenna_lever_arm_m", 3, {0, 0, 0});
  const Eigen::Vector3d lever_B(lever[0], lever[1], lever[2]);
  const gnss::ReceiverModelConfig defaults = g.model;
  g.model = profile.name == "neo-5m" ? defaults : profile.model;
  if (auto e = r.OptionalChild("errors")) {
    e->CheckKeys({"horizontal_sigma_m", "vertical_sigma_m", "correlation_time_s",
                  "velocity_sigma_mps", "common_fraction"});
    g.model.horizontal_sigma_m =
        e->DoubleIn("horizontal_sigma_m", g.model.horizontal_sigma_m, 0, 100);
    g.model.vertical_sigma_m = e->DoubleIn("vertical_sigma_m", g.model.vertical_sigma_m, 0, 100);
    g.model.correlation_time_s =
        e->DoubleIn("correlation_time_s", g.model.correlation_time_s, 0.01, 3600);
    g.model.velocity_sigma_mps =
        e->DoubleIn("velocity_sigma_mps", g.model.velocity_sigma_mps, 0, 10);
    g.model.common_fraction = e->DoubleIn("common_fraction", g.model.common_fraction, 0, 1);
  }
  g.faults.clear();
  if (auto f = r.OptionalChild("faults")) {
    if (!f->IsSequence()) f->Fail("must be a list of {kind, start_s, end_s, ...}");
    for (const YamlReader& item : f->Elements()) g.faults.push_back(ReadFault(item));
  }
  g.receivers.clear();
  if (auto list = r.OptionalChild("receivers")) {
    if (!list->IsSequence() || list->Elements().empty())
      list->Fail("must be a non-empty list of {link, antenna_lever_arm_m}");
    std::size_t i = 0;
    for (const YamlReader& item : list->Elements()) {
      item.CheckKeys({"link", "antenna_lever_arm_m"});
      GnssReceiverSpec rx;
      rx.link = item.String("link", i == 0 ? g.link : g.link + std::to_string(i));
      if (rx.link.empty() || rx.link.find('/') != std::string::npos)
        item.Fail("link", "must be a plain file name");
      const auto l = item.Doubles("antenna_lever_arm_m", 3, lever);
      rx.p_BA_B_m = Eigen::Vector3d(l[0], l[1], l[2]);
      for (const auto& other : g.receivers) {
        if (other.link == rx.link)
          item.Fail("link", "'" + rx.link + "' is used by another receiver");
      }
      g.receivers.push_back(rx);
      ++i;
    }
  } else {
    const int count = static_cast<int>(r.Int("count", 1, 1, 8));
    const double radius = r.DoubleIn("array_radius_m", 0.0, 0, 100);
    for (int i = 0; i < count; ++i) {
      const double a = 2.0 * std::numbers::pi * i / count;
      GnssReceiverSpec rx;
      rx.link = i == 0 ? g.link : g.link + std::to_string(i);
      rx.p_BA_B_m = lever_B + Eigen::Vector3d(radius * std::cos(a), radius * std::sin(a), 0.0);
      g.receivers.push_back(rx);
    }
  }
  g.link = g.receivers.front().link;
  g.model.p_BA_B_m = g.receivers.front().p_BA_B_m;
}

}  // namespace

void ReadGnssReceiverSpec(const YamlReader& root, Scenario& s) {
  GnssDeviceSpec& g = s.gnss;
  const auto r = root.OptionalChild("gnss");
  ReadSkyObstructions(root, s);
  if (r) {
    ReadGnss(*r, g);
    ReadGnssMultipath(*r, s);
    ReadRtkRoughness(*r, s);
  } else {
    g.receivers = {GnssReceiverSpec{g.link, g.model.p_BA_B_m}};
  }
  // the geoid: EGM96 at each fix's position as a u-blox 5 applies it, unless the scenario fixes N
  g.model.geoid.reset();
  if (r && r->Has("geoid_separation_m")) {
    if (r->Has("geoid")) r->Fail("geoid", "give either geoid or geoid_separation_m, not both");
    g.model.geoid_separation_m = r->DoubleIn("geoid_separation_m", 0, -200, 200);
    return;
  }
  const std::string model = r ? r->Choice("geoid", "ublox5", {"ublox5", "egm96"}) : "ublox5";
  try {
    g.model.geoid = model == "egm96" ? Egm96Geoid() : Ublox5Geoid();
  } catch (const std::exception& e) {
    const std::string why = std::string(e.what()) +
                            " (install Debian's proj-data, or fix the geoid height with "
                            "gnss.geoid_separation_m)";
    if (r) r->Fail("geoid", why);
    root.Fail(why);
  }
}

}  // namespace hil::harness

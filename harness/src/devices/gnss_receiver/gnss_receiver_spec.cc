// The `gnss` section of a scenario (owner: GNSS emulator): the receivers' profile, port, errors,
// array and fault timeline. Every key with its type, unit, default, range and source:
// gnss_receiver_keys.h (docs/scenario_reference.md, `hil scenario-keys`). Example:
//
// gnss:
//   profile: neo-5m            # or rtk
//   rate_hz: 1
//   antenna_lever_arm_m: [0, 0, 1]
//   count: 3                   # receivers on a horizontal circle around the lever arm ...
//   array_radius_m: 3.0        # ... of this radius (first one forward, then every 360/count deg)
//   errors: {horizontal_sigma_m: 0.35}
//   faults:                    # the receiver's own fault timeline (scenario seconds)
//     - {kind: outage, start_s: 30, end_s: 45}
//     - {kind: step, start_s: 80, end_s: 90, offset_m: [2, 0, 0]}     # ENU
#include <cmath>
#include <numbers>
#include <optional>

#include "gnss_receiver.h"
#include "gnss_receiver_keys.h"

namespace hil::harness {
namespace {

using gnss_keys::kErrors;
using gnss_keys::kFault;
using gnss_keys::kGnss;
using gnss_keys::kReceiver;

gnss::GnssFault ReadFault(const YamlReader& y) {
  const KeyedReader<kFault> f(y);
  f.CheckKeys();
  gnss::GnssFault g;
  g.kind = f.Choice("kind", gnss::GnssFault::Kind::kOutage);  // the table's order is the enum's
  const double start_s = f.Number("start_s", 0);
  const double end_s = f.Number("end_s", start_s);
  if (end_s <= start_s) f.Fail("end_s", "must be after start_s");
  g.start = TimeFromSeconds(start_s);
  g.end = TimeFromSeconds(end_s);
  g.elevation_deg = f.Number("elevation_deg", g.elevation_deg);
  const auto off = f.Doubles("offset_m", 3, {0, 0, 0});
  g.offset_N_m = Eigen::Vector3d(off[0], off[1], off[2]);
  g.sigma_m = f.Number("sigma_m", g.sigma_m);
  return g;
}

void ReadErrors(const YamlReader& y, gnss::ReceiverModelConfig& m) {
  const KeyedReader<kErrors> e(y);
  e.CheckKeys();
  m.horizontal_sigma_m = e.Number("horizontal_sigma_m", m.horizontal_sigma_m);
  m.vertical_sigma_m = e.Number("vertical_sigma_m", m.vertical_sigma_m);
  m.correlation_time_s = e.Number("correlation_time_s", m.correlation_time_s);
  m.velocity_sigma_mps = e.Number("velocity_sigma_mps", m.velocity_sigma_mps);
  m.common_fraction = e.Number("common_fraction", m.common_fraction);
}

// `receivers:` one by one, their lever arms defaulting to `lever`.
void ReadReceiverList(const YamlReader& list, const std::vector<double>& lever, GnssDeviceSpec& g) {
  if (!list.IsSequence() || list.Elements().empty())
    list.Fail("must be a non-empty list of {link, antenna_lever_arm_m}");
  std::size_t i = 0;
  for (const YamlReader& y : list.Elements()) {
    const KeyedReader<kReceiver> item(y);
    item.CheckKeys();
    GnssReceiverSpec rx;
    rx.link = item.String("link", i == 0 ? g.link : g.link + std::to_string(i));
    if (rx.link.empty() || rx.link.find('/') != std::string::npos)
      item.Fail("link", "must be a plain file name");
    const auto l = item.Doubles("antenna_lever_arm_m", 3, lever);
    rx.p_BA_B_m = Eigen::Vector3d(l[0], l[1], l[2]);
    for (const auto& other : g.receivers) {
      if (other.link == rx.link) item.Fail("link", "'" + rx.link + "' is used by another receiver");
    }
    g.receivers.push_back(rx);
    ++i;
  }
}

void ReadGnss(const YamlReader& y, GnssDeviceSpec& g) {
  const KeyedReader<kGnss> r(y);
  r.CheckKeys();
  g.profile = r.Choice("profile", g.profile);
  const gnss::ReceiverProfile profile = gnss::ProfileByName(g.profile);
  g.baud = static_cast<int>(r.Integer("baud", profile.baud));
  g.link = r.String("link", g.link);
  if (g.link.empty() || g.link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as ttyGPS");
  g.rate_hz = r.Number("rate_hz", profile.rate_hz);
  if (g.rate_hz > profile.max_rate_hz) {
    r.Fail("rate_hz", "above the " + g.profile + " maximum of " +
                          std::to_string(static_cast<int>(profile.max_rate_hz)) + " Hz");
  }
  g.output_lag_s = r.Number("output_lag_s", g.output_lag_s);
  g.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(g.tx_buffer_bytes)));
  g.start = r.Choice("start", gnss::StartKind::kHot);  // the table's order is the enum's
  const auto lever = r.Doubles("antenna_lever_arm_m", 3, {0, 0, 0});
  const Eigen::Vector3d lever_B(lever[0], lever[1], lever[2]);
  const gnss::ReceiverModelConfig defaults = g.model;
  g.model = profile.name == "neo-5m" ? defaults : profile.model;
  if (auto e = r.OptionalChild("errors")) ReadErrors(*e, g.model);
  g.faults.clear();
  if (auto f = r.OptionalChild("faults")) {
    if (!f->IsSequence()) f->Fail("must be a list of {kind, start_s, end_s, ...}");
    for (const YamlReader& item : f->Elements()) g.faults.push_back(ReadFault(item));
  }
  g.receivers.clear();
  if (auto list = r.OptionalChild("receivers")) {
    ReadReceiverList(*list, lever, g);
  } else {
    const int count = static_cast<int>(r.Integer("count", 1));
    const double radius = r.Number("array_radius_m", 0.0);
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
  std::optional<KeyedReader<kGnss>> k;
  if (r) k.emplace(*r);
  if (k && k->Has("geoid_separation_m")) {
    if (k->Has("geoid")) k->Fail("geoid", "give either geoid or geoid_separation_m, not both");
    g.model.geoid_separation_m = k->Number("geoid_separation_m", 0);
    return;
  }
  const std::string model = k ? k->Choice("geoid", "ublox5") : "ublox5";
  try {
    g.model.geoid = model == "egm96" ? Egm96Geoid() : Ublox5Geoid();
  } catch (const std::exception& e) {
    const std::string why = std::string(e.what()) +
                            " (install Debian's proj-data, or fix the geoid height with "
                            "gnss.geoid_separation_m)";
    if (k) k->Fail("geoid", why);
    root.Fail(why);
  }
}

}  // namespace hil::harness

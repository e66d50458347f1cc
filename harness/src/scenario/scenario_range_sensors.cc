// The `rangefinders:` and `lidar:` sections: paper 001's four Benewake rangefinders and its
// RPLIDAR, each on a pty, cast against the `greenhouse:` map. Models, mounts and rates are
// scenario parameters (the paper gives none, seeds_001_003.md A.5, A.14); defaults in
// vectors/scenarios/README.md.
#include <cstdint>

#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kRangeSensorSectionKeys{"rangefinders", "lidar"};

namespace {

// The default layout (this project's choice): the units 0.4 m apart (p_dist), 0.25 m either side
// of the centre line, 0.15 m above the floor (below the ridge tops), looking square to each side.
std::vector<RangefinderUnitSpec> DefaultUnits() {
  auto unit = [](const char* name, const char* link, double x, double y, double yaw) {
    return RangefinderUnitSpec{name, link, {x, y, 0.15, yaw}};
  };
  return {unit("right_front", "ttyRF_RF", 0.2, -0.25, -90),
          unit("right_rear", "ttyRF_RR", -0.2, -0.25, -90),
          unit("left_front", "ttyRF_LF", 0.2, 0.25, 90),
          unit("left_rear", "ttyRF_LR", -0.2, 0.25, 90)};
}

void ReadReflectivity(const YamlReader& r, world::SurfaceReflectivity& f) {
  r.CheckKeys({"ridge", "post", "wall"});
  f.ridge = r.DoubleIn("ridge", f.ridge, 0.001, 2);
  f.post = r.DoubleIn("post", f.post, 0.001, 2);
  f.wall = r.DoubleIn("wall", f.wall, 0.001, 2);
}

std::vector<RangefinderUnitSpec> ReadUnits(const YamlReader& r) {
  std::vector<RangefinderUnitSpec> units;
  for (const YamlReader& u : r.Elements()) {
    u.CheckKeys({"name", "link", "mount_m", "yaw_deg"});
    RangefinderUnitSpec spec;
    spec.name = u.String("name");
    spec.link = u.String("link", "ttyRF_" + spec.name);
    const std::vector<double> m = u.Doubles("mount_m", 3, {0, 0, 0.15});
    spec.mount = {m[0], m[1], m[2], u.DoubleIn("yaw_deg", -90, -360, 360)};
    if (m[2] < 0) u.Fail("mount_m", "the height must not be negative");
    for (const auto& other : units) {
      if (other.name == spec.name) u.Fail("name", "two units named '" + spec.name + "'");
      if (other.link == spec.link) u.Fail("link", "two units on link '" + spec.link + "'");
    }
    units.push_back(spec);
  }
  if (units.empty()) r.Fail("needs at least one unit");
  return units;
}

void ReadRangefinders(const YamlReader& r, RangefinderSpec& spec) {
  r.CheckKeys({"model", "baud", "rate_hz", "format", "units", "reflectivity", "tx_buffer_bytes"});
  spec.enabled = true;
  rangefinder::TfLunaConfig& m = spec.module;
  m.model.model = r.Choice("model", "tf_luna", {"tf_luna", "tfmini_s"}) == "tf_luna"
                      ? rangefinder::ModuleModel::kTfLuna
                      : rangefinder::ModuleModel::kTfminiS;
  m.settings.baud = static_cast<std::uint32_t>(r.Int("baud", 115200, 9600, 921600));
  if (!rangefinder::IsSupportedBaud(m.settings.baud))
    r.Fail("baud", "not a baud rate of the TF-Luna manual");
  m.settings.frame_rate_hz = static_cast<std::uint16_t>(r.Int("rate_hz", 100, 1, 250));
  m.settings.format = r.Choice("format", "cm", {"cm", "mm"}) == "cm"
                          ? rangefinder::OutputFormat::kCm9Byte
                          : rangefinder::OutputFormat::kMm9Byte;
  if (auto f = r.OptionalChild("reflectivity")) ReadReflectivity(*f, m.reflectivity);
  spec.units = r.Has("units") ? ReadUnits(r.Child("units")) : DefaultUnits();
  spec.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 4096, 64, 1 << 20));
}

void ReadLidar(const YamlReader& r, LidarSpec& spec) {
  r.CheckKeys({"model", "link", "rotation_hz", "mount_m", "yaw_deg", "spin_up_s",
               "range_sigma_fraction", "reflectivity", "tx_buffer_bytes"});
  spec.enabled = true;
  lidar::RplidarConfig& c = spec.config;
  const bool a2 = r.Choice("model", "a1m8", {"a1m8", "a2m8"}) == "a2m8";
  c.model = a2 ? lidar::RplidarModel::kA2M8 : lidar::RplidarModel::kA1M8;
  if (a2) c.info.model = 0x28;  // UNVERIFIED model byte of the A2M8
  spec.link = r.String("link", spec.link);
  c.rotation_hz = r.DoubleIn("rotation_hz", c.rotation_hz, 1, 15);
  const std::vector<double> m = r.Doubles("mount_m", 3, {0, 0, 0.4});
  c.mount = {m[0], m[1], m[2], r.DoubleIn("yaw_deg", 0, -360, 360)};
  c.spin_up = DurationFromSeconds(r.DoubleIn("spin_up_s", ToSeconds(c.spin_up), 0, 10));
  c.range_sigma_fraction = r.DoubleIn("range_sigma_fraction", c.range_sigma_fraction, 0, 0.1);
  if (auto f = r.OptionalChild("reflectivity")) ReadReflectivity(*f, c.reflectivity);
  spec.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 16384, 64, 1 << 20));
}

}  // namespace

void ReadRangeSensorSections(const YamlReader& root, Scenario& s) {
  for (const char* key : {"rangefinders", "lidar"}) {
    if (root.Has(key) && !s.greenhouse) root.Fail(key, "needs a greenhouse: section to sense");
  }
  if (auto r = root.OptionalChild("rangefinders")) ReadRangefinders(*r, s.rangefinders);
  if (auto l = root.OptionalChild("lidar")) ReadLidar(*l, s.lidar);
  if (s.lidar.enabled) {
    for (const auto& u : s.rangefinders.units) {
      if (u.link == s.lidar.link)
        root.Child("lidar").Fail("link", "'" + u.link + "' is a rangefinder's link already");
    }
  }
}

}  // namespace hil::harness

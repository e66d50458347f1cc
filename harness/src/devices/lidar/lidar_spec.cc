// The `lidar:` section: paper 001's RPLIDAR on a pty, cast against the `greenhouse:` map. Its
// mount and rate are scenario parameters (the paper gives none, seeds_001_003.md A.14); defaults
// in vectors/scenarios/README.md.
#include "lidar.h"

namespace hil::harness {
namespace {

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
  if (auto f = r.OptionalChild("reflectivity")) ReadSurfaceReflectivity(*f, c.reflectivity);
  spec.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 16384, 64, 1 << 20));
}

}  // namespace

void ReadLidarSpec(const YamlReader& root, Scenario& s) {
  if (root.Has("lidar") && !s.greenhouse)
    root.Fail("lidar", "needs a greenhouse: section to sense");
  if (auto l = root.OptionalChild("lidar")) ReadLidar(*l, s.lidar);
  if (s.lidar.enabled) {  // the rangefinders row is read before this one
    for (const auto& u : s.rangefinders.units) {
      if (u.link == s.lidar.link)
        root.Child("lidar").Fail("link", "'" + u.link + "' is a rangefinder's link already");
    }
  }
}

}  // namespace hil::harness

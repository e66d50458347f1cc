// The `lidar:` section: paper 001's RPLIDAR on a pty, cast against the `greenhouse:` map. Its
// mount and rate are scenario parameters (the paper gives none, seeds_001_003.md A.14); defaults
// in vectors/scenarios/README.md.
#include <array>
#include <string_view>

#include "lidar.h"

namespace hil::harness {
namespace lidar_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::array<std::string_view, 2> kLidarModels{"a1m8", "a2m8"};

inline constexpr ScenarioKey kLidar[] = {
    {"model", kChoice, "", "a1m8", 0, 0,
     "Slamtec RPLIDAR A1M8, or A2M8 (SET_MOTOR_PWM, accessory flag 1)", kLidarModels},
    {"link", kString, "", "ttyLIDAR", 0, 0, "its pty in the run folder"},
    {"rotation_hz", kNumber, "Hz", "5.5", 1, 15, "scan rotation rate"},
    {"mount_m", kPoint, "m", "[0, 0, 0.4]", 0, 0,
     "[x, y, z] in the body frame FLU (z: the scan plane's height)"},
    {"yaw_deg", kNumber, "deg", "0", -360, 360,
     "its forward axis, counter-clockwise from the body's"},
    {"spin_up_s", kNumber, "s", "0.5", 0, 10, "motor start to stable rotation"},
    {"range_sigma_fraction", kNumber, "", "0.005", 0, 0.1, "range noise, a fraction of the range"},
    {"reflectivity", kMapping, "", "ridge 0.25, post 0.5, wall 0.05", 0, 0,
     "what the beams see (section lidar.reflectivity)"},
    {"tx_buffer_bytes", kInteger, "B", "16384", 64, 1 << 20, "its UART's transmit buffer"},
};

}  // namespace lidar_keys

namespace {

using lidar_keys::kLidar;

void ReadLidar(const YamlReader& y, LidarSpec& spec) {
  const KeyedReader<kLidar> r(y);
  r.CheckKeys();
  spec.enabled = true;
  lidar::RplidarConfig& c = spec.config;
  const bool a2 = r.Choice("model", "a1m8") == "a2m8";
  c.model = a2 ? lidar::RplidarModel::kA2M8 : lidar::RplidarModel::kA1M8;
  if (a2) c.info.model = 0x28;  // UNVERIFIED model byte of the A2M8
  spec.link = r.String("link", spec.link);
  c.rotation_hz = r.Number("rotation_hz", c.rotation_hz);
  const std::vector<double> m = r.Doubles("mount_m", 3, {0, 0, 0.4});
  c.mount = {m[0], m[1], m[2], r.Number("yaw_deg", 0)};
  c.spin_up = DurationFromSeconds(r.Number("spin_up_s", ToSeconds(c.spin_up)));
  c.range_sigma_fraction = r.Number("range_sigma_fraction", c.range_sigma_fraction);
  if (auto f = r.OptionalChild("reflectivity")) ReadSurfaceReflectivity(*f, c.reflectivity);
  spec.tx_buffer_bytes = static_cast<std::size_t>(r.Integer("tx_buffer_bytes", 16384));
}

}  // namespace

extern const KeySection kLidarSection{
    "lidar", "paper 001's Slamtec RPLIDAR on a pty, cast against the greenhouse (needs greenhouse)",
    kLidar};

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

// Pieces the device kinds' spec readers share (device_kind.h).
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

std::string ReadLinkName(const YamlReader& r, const std::string& fallback) {
  const std::string link = r.String("link", fallback);
  if (link.empty() || link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as " + fallback);
  return link;
}

namespace reflectivity_keys {

using enum KeyType;

inline constexpr ScenarioKey kReflectivity[] = {
    {"ridge", kNumber, "", "0.25", 0.001, 2, "the ridges' reflectivity"},
    {"post", kNumber, "", "0.5", 0.001, 2, "the posts'"},
    {"wall", kNumber, "", "0.05", 0.001, 2, "the walls' (film walls return little)"},
};

}  // namespace reflectivity_keys

using reflectivity_keys::kReflectivity;

extern const KeySection kReflectivitySection{
    "lidar.reflectivity",
    "the greenhouse's surfaces as the range sensors see them (rangefinders.reflectivity alike)",
    kReflectivity};

void ReadSurfaceReflectivity(const YamlReader& r, world::SurfaceReflectivity& f) {
  const KeyedReader<kReflectivity> keyed(r);
  keyed.CheckKeys();
  f.ridge = keyed.Number("ridge", f.ridge);
  f.post = keyed.Number("post", f.post);
  f.wall = keyed.Number("wall", f.wall);
}

}  // namespace hil::harness

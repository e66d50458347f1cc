// Pieces the device kinds' spec readers share (device_kind.h).
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

std::string ReadLinkName(const YamlReader& r, const std::string& fallback) {
  const std::string link = r.String("link", fallback);
  if (link.empty() || link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as " + fallback);
  return link;
}

void ReadSurfaceReflectivity(const YamlReader& r, world::SurfaceReflectivity& f) {
  r.CheckKeys({"ridge", "post", "wall"});
  f.ridge = r.DoubleIn("ridge", f.ridge, 0.001, 2);
  f.post = r.DoubleIn("post", f.post, 0.001, 2);
  f.wall = r.DoubleIn("wall", f.wall, 0.001, 2);
}

}  // namespace hil::harness

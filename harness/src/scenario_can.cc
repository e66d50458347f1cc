#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kCanSectionKeys{"can"};

void ReadCanSection(const YamlReader& root, CanLinkSpec& c) {
  auto r = root.OptionalChild("can");
  if (!r) return;
  r->CheckKeys({"interface", "fd"});
  c.interface = r->String("interface");
  if (c.interface.empty() || c.interface.size() > 15 || c.interface.find_first_of("/ \t") != std::string::npos) {
    r->Fail("interface", "must be a network interface name such as vcan0 or can0");
  }
  c.fd = r->Bool("fd", false);
}

}  // namespace hil::harness

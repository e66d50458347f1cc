#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kCanSectionKeys{"can"};

void ReadCanSection(const YamlReader& root, CanLinkSpec& c) {
  auto r = root.OptionalChild("can");
  if (!r) return;
  r->CheckKeys({"interface", "fd", "imu_to_estimator"});
  c.interface = r->String("interface");
  if (c.interface.empty() || c.interface.size() > 15 ||
      c.interface.find_first_of("/ \t") != std::string::npos) {
    r->Fail("interface", "must be a network interface name such as vcan0 or can0");
  }
  c.fd = r->Bool("fd", false);
  c.imu_to_estimator = r->Bool("imu_to_estimator", false);
}

void CheckCanUse(const YamlReader& root, const Scenario& s) {
  if (s.can.imu_to_estimator && !(s.mcu.enabled && s.mcu.config.can.enabled)) {
    root.OptionalChild("can")->Fail("imu_to_estimator",
                                    "needs an mcu section with can: {enabled: true}");
  }
  if (s.estimator.output == EstimatorOutput::kN2kSocketcan && s.can.interface.empty()) {
    root.OptionalChild("estimator")
        ->Fail("output", "n2k_socketcan reads the CAN bus: the scenario needs can: {interface: …}");
  }
}

}  // namespace hil::harness

#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kCanSectionKeys{"can"};

namespace can_keys {  // named: the unity build joins the readers' files

using enum KeyType;

inline constexpr ScenarioKey kCan[] = {
    {"interface", kString, "", "required", 0, 0,
     "the SocketCAN interface (vcan0, can0) the devices' CAN frames go out on (captured as "
     "captures/<interface>.candump)"},
    {"fd", kBool, "", "false", 0, 0, "open the socket for CAN FD frames"},
    {"imu_to_estimator", kBool, "", "false", 0, 0,
     "navd reads the MCU's J1939 IMU frames from this bus instead of its serial link (needs "
     "mcu.can.enabled and --mode realtime or scaled)"},
};

}  // namespace can_keys

extern const KeySection kCanSection{"can", "the CAN bus (SocketCAN)", can_keys::kCan};

void ReadCanSection(const YamlReader& root, CanLinkSpec& c) {
  auto y = root.OptionalChild("can");
  if (!y) return;
  const KeyedReader<can_keys::kCan> r(*y);
  r.CheckKeys();
  c.interface = r.String("interface");
  if (c.interface.empty() || c.interface.size() > 15 ||
      c.interface.find_first_of("/ \t") != std::string::npos) {
    r.Fail("interface", "must be a network interface name such as vcan0 or can0");
  }
  c.fd = r.Bool("fd", false);
  c.imu_to_estimator = r.Bool("imu_to_estimator", false);
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

#include "hil/harness/run/device_set.h"

namespace hil::harness {

DeviceSet BuildDevices(const Scenario& scenario, std::uint64_t seed, const std::string& run_dir) {
  DeviceSet set;
  if (!scenario.can.interface.empty()) {
    set.can = std::make_unique<CanEndpoint>(scenario.can.interface, run_dir + "/captures",
                                            scenario.start_utc, scenario.can.fd);
  }
  for (const DeviceKind* k : DeviceKinds())
    k->build(scenario, seed * kSeedStride + k->seed_stream, run_dir, set);
  return set;
}

}  // namespace hil::harness

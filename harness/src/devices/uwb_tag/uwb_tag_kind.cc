// Paper 003's devices in the run's device set: the UWB tag (`uwb:`) and the WT901C (`wt901c:`),
// each on its own pty (RUN_DIR/ttyUWB, RUN_DIR/ttyWIT by default).
#include "device_set_paper003.h"

#include "hil/firmware_emu/attitude/wt901c_device.h"
#include "hil/firmware_emu/uwb/uwb_tag_device.h"

namespace hil::harness {
namespace {

void AddPort(const std::string& link, int baud, std::size_t tx_buffer, const std::string& dir,
             std::unique_ptr<Device> dev, DeviceSet& set) {
  const std::string path = dir + "/" + link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(link, path, baud, tx_buffer,
                                                   dir + "/captures/" + link + ".cap"));
  set.links.emplace_back(link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

}  // namespace

void AddPaper003Devices(const Scenario& s, std::uint64_t uwb_seed, std::uint64_t wit_seed,
                        const std::string& dir, DeviceSet& set) {
  if (s.uwb.enabled) {
    auto dev = std::make_unique<uwb::UwbTagDevice>(s.uwb.config, uwb_seed);
    const int baud = dev->baud(0);
    AddPort(s.uwb.link, baud, s.uwb.tx_buffer_bytes, dir, std::move(dev), set);
  }
  if (s.wt901c.enabled) {
    auto dev = std::make_unique<wit::Wt901cDevice>(s.wt901c.config, wit_seed);
    const int baud = dev->baud(0);
    AddPort(s.wt901c.link, baud, s.wt901c.tx_buffer_bytes, dir, std::move(dev), set);
  }
}

}  // namespace hil::harness

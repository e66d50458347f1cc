// The RTK base in the run's device set: its RTCM 3 stream, after the correction radio, on its own
// pty with a capture, as a radio modem's UART would deliver it to the rover.
#include "device_set_rtk.h"

#include "hil/firmware_emu/rtk/rtk_base_device.h"

namespace hil::harness {

void AddRtkBase(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  if (!s.rtk_base.enabled) return;
  auto dev = std::make_unique<rtk::RtkBaseDevice>(s.rtk_base.config, seed);
  const std::string& link = s.rtk_base.link;
  const std::string path = dir + "/" + link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(
      link, path, dev->baud(0), s.rtk_base.tx_buffer_bytes, dir + "/captures/" + link + ".cap"));
  set.links.emplace_back(link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

}  // namespace hil::harness

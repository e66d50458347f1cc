#include "device_set_isobus.h"

namespace hil::harness {

void AddIsobusSteering(const Scenario& s, const std::string& dir, DeviceSet& set) {
  const ClosedLoopSpec& c = s.closed_loop;
  if (!c.enabled || c.channel != ClosedLoopSpec::Channel::kIsobus) return;
  actuator::IsobusSteeringDeviceConfig cfg = c.isobus;
  for (const Fault& f : s.faults.OfKind(FaultKind::kCommandLinkLoss))
    cfg.link_loss.emplace_back(f.start, f.end);
  auto dev = std::make_unique<actuator::IsobusSteeringDevice>(cfg);
  dev->ReserveTicks(static_cast<std::size_t>(s.duration_s / c.control_period_s) + 2);
  set.steering = dev.get();
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  if (cfg.transport == actuator::IsobusTransport::kSlcan) {
    const std::string path = dir + "/" + c.link;
    ports.push_back(std::make_unique<SerialEndpoint>(c.link, path, cfg.slcan_baud, 4096,
                                                     dir + "/captures/" + c.link + ".cap"));
    set.links.emplace_back(c.link, path);
  }
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

}  // namespace hil::harness

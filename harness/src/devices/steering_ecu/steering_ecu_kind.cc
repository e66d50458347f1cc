// The steering ECU's row of the device table: a closed loop's ISOBUS steering ECU (channel
// isobus), on the run's CAN bus (transport socketcan) or behind a serial SLCAN adapter on
// RUN_DIR/<link> (slcan).
#include "hil/harness/devices/device_kind.h"

namespace hil::harness {
namespace {

bool HasSteeringEcu(const Scenario& s) {
  return s.closed_loop.enabled && s.closed_loop.channel == ClosedLoopSpec::Channel::kIsobus;
}

void BuildSteeringEcu(const Scenario& s, std::uint64_t /*seed*/, const std::string& dir,
                      DeviceBuild& set) {
  if (!HasSteeringEcu(s)) return;
  const ClosedLoopSpec& c = s.closed_loop;
  actuator::IsobusSteeringDeviceConfig cfg = c.isobus;
  for (const Fault& f : s.faults.OfKind(FaultKind::kCommandLinkLoss))
    cfg.link_loss.emplace_back(f.start, f.end);
  auto dev = std::make_unique<actuator::IsobusSteeringDevice>(cfg);
  set.steering = dev.get();
  if (cfg.transport == actuator::IsobusTransport::kSlcan) {
    AddSerialDevice(std::move(dev), c.link, 4096, dir, set, cfg.slcan_baud);
    return;
  }
  set.devices.push_back(std::move(dev));
  set.endpoints.emplace_back();  // no serial port: its frames go out on the CAN bus
}

std::vector<std::string> SteeringEcuLinks(const Scenario& s) {
  if (!HasSteeringEcu(s) || s.closed_loop.isobus.transport != actuator::IsobusTransport::kSlcan)
    return {};
  return {s.closed_loop.link};
}

// The header's line: the transport and the set speed.
std::string SteeringEcuProfile(const Scenario& s) {
  const auto& c = s.closed_loop.isobus;
  return ProfileText("ISO 11783-7 steering ECU over %s, set speed %g m/s",
                     c.transport == actuator::IsobusTransport::kSlcan ? "slcan" : "SocketCAN",
                     c.speed_mps);
}

}  // namespace

extern const DeviceKind kSteeringEcuKind;
const DeviceKind kSteeringEcuKind{
    .name = "steering_ecu",
    .sections = {},
    .spec = "closed_loop: with channel isobus (transport, actuator:; read with the loop)",
    .read = nullptr,
    .seed_stream = 0,
    .build = BuildSteeringEcu,
    .navd_keys = {},
    .write_navd = nullptr,
    .links = SteeringEcuLinks,
    .navd_links = nullptr,
    .report_section = "closed_loop",
    .link_role = "",
    .profile = SteeringEcuProfile};

}  // namespace hil::harness

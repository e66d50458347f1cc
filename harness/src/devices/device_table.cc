// The device table (device_kind.h): one row per kind of device, in build order. Each kind's row is
// defined in its folder (harness/src/devices/<kind>/<kind>_kind.cc), as gpsd's drivers are.
#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "hil/harness/devices/device_kind.h"

namespace hil::harness {

extern const DeviceKind kGnssReceiverKind;  // gnss_receiver/: NEO-5M (or RTK) receivers
extern const DeviceKind kMcuKind;           // mcu/: the IMU board's MCU, serial and CAN
extern const DeviceKind kUwbTagKind;        // uwb_tag/: the UWB tag
extern const DeviceKind kWt901cKind;        // wt901c/: the WT901C attitude sensor
extern const DeviceKind kRangefindersKind;  // rangefinders/: TF-Luna / TFmini-S units
extern const DeviceKind kLidarKind;         // lidar/: the RPLIDAR
extern const DeviceKind kRtkBaseKind;       // rtk_base/: RTK reference station and radio
extern const DeviceKind kZedF9pKind;        // zed_f9p/: the ZED-F9P RTK rover
extern const DeviceKind kWheelBaseKind;     // wheel_base/: the diff-drive base and its encoders
extern const DeviceKind kSteeringEcuKind;   // steering_ecu/: the ISOBUS steering ECU

namespace {

// The order is the devices' order in the run (their events at equal times go in this order).
constexpr const DeviceKind* kTable[] = {
    &kGnssReceiverKind, &kMcuKind,     &kUwbTagKind, &kWt901cKind,    &kRangefindersKind,
    &kLidarKind,        &kRtkBaseKind, &kZedF9pKind, &kWheelBaseKind, &kSteeringEcuKind,
};

}  // namespace

std::span<const DeviceKind* const> DeviceKinds() { return kTable; }

std::string ProfileText(const char* format, ...) {
  char b[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(b, sizeof b, format, args);
  va_end(args);
  return b;
}

const DeviceKind* DeviceKindOfLink(const Scenario& s, const std::string& link) {
  for (const DeviceKind* k : kTable) {
    const std::vector<std::string> links = k->links(s);
    if (std::find(links.begin(), links.end(), link) != links.end()) return k;
  }
  return nullptr;
}

const world::GreenhouseWorld& GreenhouseWorldOf(const Scenario& s, DeviceBuild& set) {
  if (!set.world) set.world = std::make_unique<world::GreenhouseWorld>(*s.greenhouse);
  return *set.world;
}

void AddSerialDevice(std::unique_ptr<Device> dev, const std::string& link, std::size_t tx_buffer,
                     const std::string& run_dir, DeviceBuild& set, int baud) {
  const std::string path = run_dir + "/" + link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(link, path, baud > 0 ? baud : dev->baud(0),
                                                   tx_buffer,
                                                   run_dir + "/captures/" + link + ".cap"));
  set.links.emplace_back(link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

}  // namespace hil::harness

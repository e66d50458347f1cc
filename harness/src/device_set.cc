#include "hil/harness/device_set.h"

#include "hil/firmware_emu/gnss/nmea_receiver_device.h"
#include "hil/firmware_emu/mcu/mcu_device.h"

namespace hil::harness {
namespace {

// Seeds of independent random streams derived from the run's seed.
constexpr std::uint64_t kSeedStride = 1000003ULL;
enum SeedStream : std::uint64_t { kGnssStream = 1, kMcuStream = 2 };

void AddGnss(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  gnss::NmeaReceiverConfig cfg;
  cfg.baud = s.gnss.baud;
  cfg.rate_hz = s.gnss.rate_hz;
  cfg.output_lag = DurationFromSeconds(s.gnss.output_lag_s);
  cfg.start_unix_ns = s.start_unix_ns;
  cfg.model = s.gnss.model;
  auto dev = std::make_unique<gnss::NmeaReceiverDevice>(cfg, seed * kSeedStride + kGnssStream);
  const gnss::NmeaReceiverDevice* raw = dev.get();
  set.fix_sources.push_back([raw] { return &raw->last_fix(); });
  const std::string path = dir + "/" + s.gnss.link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(s.gnss.link, path, s.gnss.baud, s.gnss.tx_buffer_bytes,
                                                   dir + "/captures/" + s.gnss.link + ".cap"));
  set.links.emplace_back(s.gnss.link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

// The IMU board's microcontroller, when the scenario has an `mcu:` section: one serial link
// (RUN_DIR/<link>, e.g. ttyIMU); its CAN frames leave through DeviceOutput::can.
void AddMcu(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  if (!s.mcu.enabled) return;
  mcu::McuConfig cfg = s.mcu.config;
  cfg.start_unix_ns = s.start_unix_ns;
  auto dev = std::make_unique<mcu::McuDevice>(cfg, seed * kSeedStride + kMcuStream);
  const std::string path = dir + "/" + s.mcu.link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(s.mcu.link, path, cfg.baud, s.mcu.tx_buffer_bytes,
                                                   dir + "/captures/" + s.mcu.link + ".cap"));
  set.links.emplace_back(s.mcu.link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

}  // namespace

DeviceSet BuildDevices(const Scenario& scenario, std::uint64_t seed, const std::string& run_dir) {
  DeviceSet set;
  AddGnss(scenario, seed, run_dir, set);
  AddMcu(scenario, seed, run_dir, set);
  return set;
}

}  // namespace hil::harness

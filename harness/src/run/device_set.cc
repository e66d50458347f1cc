#include "hil/harness/run/device_set.h"

#include "hil/firmware_emu/gnss/neo5m_device.h"
#include "hil/firmware_emu/lidar/rplidar_device.h"
#include "hil/firmware_emu/mcu/mcu_device.h"
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include "device_set_isobus.h"
#include "device_set_paper003.h"
#include "device_set_rtk.h"

namespace hil::harness {
namespace {

// Seeds of independent random streams derived from the run's seed.
constexpr std::uint64_t kSeedStride = 1000003ULL;
enum SeedStream : std::uint64_t {
  kGnssStream = 1,
  kMcuStream = 2,
  kUwbStream = 3,
  kWitStream = 4,
  kRangefinderStream = 5,
  kLidarStream = 6,
  kBaseStream = 7,
  kRtkBaseStream = 8
};
constexpr std::uint64_t kUnitStride = 104729;        // each rangefinder unit's own stream
constexpr std::uint64_t kGnssCommonOffset = 0x5151;  // the error part shared by all receivers
constexpr std::uint64_t kReceiverStride = 7919;      // each receiver's own part

// One Neo5mDevice per receiver of the gnss section, each on its own pty (ttyGPS, ttyGPS1, ...).
void AddGnss(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  const std::uint64_t base = seed * kSeedStride + kGnssStream;
  for (std::size_t i = 0; i < s.gnss.receivers.size(); ++i) {
    const GnssReceiverSpec& rx = s.gnss.receivers[i];
    gnss::Neo5mConfig cfg;
    cfg.name = "gps" + std::to_string(i);
    cfg.profile = s.gnss.profile;
    cfg.baud = s.gnss.baud;
    cfg.rate_hz = s.gnss.rate_hz;
    cfg.output_lag = DurationFromSeconds(s.gnss.output_lag_s);
    cfg.start_unix_ns = s.start_unix_ns;
    cfg.model = s.gnss.model;
    cfg.model->p_BA_B_m = rx.p_BA_B_m;
    cfg.start = s.gnss.start;
    cfg.faults = s.gnss.faults;
    // the scenario's global fault timeline: outages, data gaps and glitches reach every receiver
    for (const Fault& f : s.faults.faults) {
      gnss::GnssFault g;
      g.start = f.start;
      g.end = f.end;
      if (f.kind == FaultKind::kGnssOutage) {
        g.kind = gnss::GnssFault::Kind::kOutage;
      } else if (f.kind == FaultKind::kGnssDataGap) {
        g.kind = gnss::GnssFault::Kind::kDataGap;
      } else if (f.kind == FaultKind::kGnssGlitch) {
        g.kind = gnss::GnssFault::Kind::kStep;
        g.offset_N_m =
            Eigen::Vector3d(f.Param("east_m", 0), f.Param("north_m", 0), f.Param("up_m", 0));
      } else if (f.kind == FaultKind::kGnssOverload) {
        g.kind = gnss::GnssFault::Kind::kOverload;
      } else {
        continue;
      }
      cfg.faults.push_back(g);
    }
    cfg.common_seed = base + kGnssCommonOffset;
    auto dev = std::make_unique<gnss::Neo5mDevice>(cfg, base + kReceiverStride * i);
    const gnss::Neo5mDevice* raw = dev.get();
    set.fix_sources.push_back([raw] { return &raw->last_fix(); });
    const std::string path = dir + "/" + rx.link;
    std::vector<std::unique_ptr<SerialEndpoint>> ports;
    ports.push_back(std::make_unique<SerialEndpoint>(rx.link, path, dev->baud(0),
                                                     s.gnss.tx_buffer_bytes,
                                                     dir + "/captures/" + rx.link + ".cap"));
    set.links.emplace_back(rx.link, path);
    set.devices.push_back(std::move(dev));
    set.endpoints.push_back(std::move(ports));
  }
}

// The IMU board's microcontroller, when the scenario has an `mcu:` section: one serial link
// (RUN_DIR/<link>, e.g. ttyIMU); its CAN frames leave through DeviceOutput::can.
void AddMcu(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  if (!s.mcu.enabled) return;
  mcu::McuConfig cfg = s.mcu.config;
  cfg.start_unix_ns = s.start_unix_ns;
  // the scenario's global fault timeline: an mcu_reset keeps the MCU silent until its end
  for (const Fault& f : s.faults.OfKind(FaultKind::kMcuReset)) {
    mcu::McuFault r;
    r.kind = mcu::FaultKind::kReset;
    r.start = f.start;
    r.duration = f.end - f.start;
    cfg.faults.push_back(r);
  }
  auto dev = std::make_unique<mcu::McuDevice>(cfg, seed * kSeedStride + kMcuStream);
  const std::string path = dir + "/" + s.mcu.link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(
      s.mcu.link, path, cfg.baud, s.mcu.tx_buffer_bytes, dir + "/captures/" + s.mcu.link + ".cap"));
  set.links.emplace_back(s.mcu.link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

// One serial link for a device: RUN_DIR/<link> with its capture.
void AddSerial(std::unique_ptr<Device> dev, const std::string& link, std::size_t tx_buffer,
               const std::string& dir, DeviceSet& set) {
  const std::string path = dir + "/" + link;
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  ports.push_back(std::make_unique<SerialEndpoint>(link, path, dev->baud(0), tx_buffer,
                                                   dir + "/captures/" + link + ".cap"));
  set.links.emplace_back(link, path);
  set.devices.push_back(std::move(dev));
  set.endpoints.push_back(std::move(ports));
}

// Paper 001's range sensors: one TfLunaDevice per rangefinder unit and the RPLIDAR, each on its
// own pty, all casting against the scenario's greenhouse.
void AddRangeSensors(const Scenario& s, std::uint64_t seed, const std::string& dir,
                     DeviceSet& set) {
  if (!s.greenhouse || (!s.rangefinders.enabled && !s.lidar.enabled)) return;
  set.world = std::make_unique<world::GreenhouseWorld>(*s.greenhouse);
  const std::uint64_t base = seed * kSeedStride + kRangefinderStream;
  for (std::size_t i = 0; i < s.rangefinders.units.size(); ++i) {
    const RangefinderUnitSpec& u = s.rangefinders.units[i];
    rangefinder::TfLunaConfig cfg = s.rangefinders.module;
    cfg.name = "rf_" + u.name;
    cfg.mount = u.mount;
    AddSerial(std::make_unique<rangefinder::TfLunaDevice>(cfg, *set.world, base + kUnitStride * i),
              u.link, s.rangefinders.tx_buffer_bytes, dir, set);
  }
  if (s.lidar.enabled) {
    AddSerial(std::make_unique<lidar::RplidarDevice>(s.lidar.config, *set.world,
                                                     seed * kSeedStride + kLidarStream),
              s.lidar.link, s.lidar.tx_buffer_bytes, dir, set);
  }
}

// Closed loop: the wheel-motor faults of the scenario's fault timeline (wheel_motor_faults.h).
std::vector<actuator::WheelMotorFault> WheelMotorFaultsOf(const FaultTimeline& timeline) {
  using K = actuator::WheelMotorFault::Kind;
  std::vector<actuator::WheelMotorFault> out;
  for (std::size_t i = 0; i < timeline.faults.size(); ++i) {
    const Fault& f = timeline.faults[i];
    actuator::WheelMotorFault w;
    if (f.kind == FaultKind::kCommandLatency) {
      w.kind = K::kCommandLatency;
      w.latency = DurationFromSeconds(f.Param("latency_s", 0));
      w.jitter = DurationFromSeconds(f.Param("jitter_s", 0));
    } else if (f.kind == FaultKind::kActuatorSaturation) {
      w.kind = K::kSaturation;
      w.max_wheel_speed_radps = f.Param("max_wheel_speed_radps", 0);
    } else if (f.kind == FaultKind::kActuatorStuck) {
      w.kind = K::kStuck;
    } else {
      continue;
    }
    w.start = f.start;
    w.end = f.end;
    w.timeline_index = i;
    out.push_back(w);
  }
  return out;
}

// Closed loop: the differential-drive base on its serial link (RUN_DIR/<link>, e.g. ttyBASE).
void AddBase(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceSet& set) {
  const ClosedLoopSpec& c = s.closed_loop;
  if (!c.enabled || c.channel != ClosedLoopSpec::Channel::kSerialBase) return;
  actuator::BaseSerialDeviceConfig cfg;
  cfg.motors = c.motors;
  cfg.motors.faults = WheelMotorFaultsOf(s.faults);
  cfg.motors.fault_seed = seed * kSeedStride + kBaseStream;
  cfg.serial.pid_rate_hz = c.pid_rate_hz;
  cfg.control_period = DurationFromSeconds(c.control_period_s);
  cfg.command_timeout = DurationFromSeconds(c.command_timeout_s);
  cfg.first_command_due = TimeFromSeconds(c.first_command_due_s);
  for (const Fault& f : s.faults.OfKind(FaultKind::kCommandLinkLoss))
    cfg.link_loss.emplace_back(f.start, f.end);
  auto dev = std::make_unique<actuator::BaseSerialDevice>(cfg);
  dev->ReserveTicks(static_cast<std::size_t>(s.duration_s / c.control_period_s) + 2);
  set.base = dev.get();
  AddSerial(std::move(dev), c.link, 4096, dir, set);
}

}  // namespace

DeviceSet BuildDevices(const Scenario& scenario, std::uint64_t seed, const std::string& run_dir) {
  DeviceSet set;
  if (!scenario.can.interface.empty()) {
    set.can = std::make_unique<CanEndpoint>(scenario.can.interface, run_dir + "/captures",
                                            scenario.start_unix_ns, scenario.can.fd);
  }
  AddGnss(scenario, seed, run_dir, set);
  AddMcu(scenario, seed, run_dir, set);
  AddPaper003Devices(scenario, seed * kSeedStride + kUwbStream, seed * kSeedStride + kWitStream,
                     run_dir, set);
  AddRangeSensors(scenario, seed, run_dir, set);
  AddRtkBase(scenario, seed * kSeedStride + kRtkBaseStream, run_dir, set);
  AddBase(scenario, seed, run_dir, set);
  AddIsobusSteering(scenario, run_dir, set);
  return set;
}

}  // namespace hil::harness

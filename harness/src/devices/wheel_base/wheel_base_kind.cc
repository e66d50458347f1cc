// The wheel base's row of the device table: a closed loop's differential-drive base (channel
// serial_base; ROSArduinoBridge on RUN_DIR/<link>, e.g. ttyBASE) with its wheel motors and
// encoders; navd's gyro_odometry mode reads its encoder counts ([odometry]).
#include "wheel_base.h"

namespace hil::harness {
namespace {

// The wheel-motor faults of the scenario's fault timeline (wheel_motor_faults.h).
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

bool HasWheelBase(const Scenario& s) {
  return s.closed_loop.enabled && s.closed_loop.channel == ClosedLoopSpec::Channel::kSerialBase;
}

void BuildWheelBase(const Scenario& s, std::uint64_t seed, const std::string& dir,
                    DeviceBuild& set) {
  if (!HasWheelBase(s)) return;
  const ClosedLoopSpec& c = s.closed_loop;
  actuator::BaseSerialDeviceConfig cfg;
  cfg.motors = c.motors;
  cfg.motors.faults = WheelMotorFaultsOf(s.faults);
  cfg.motors.fault_seed = seed;
  cfg.serial.pid_rate_hz = c.pid_rate_hz;
  cfg.control_period = DurationFromSeconds(c.control_period_s);
  cfg.command_timeout = DurationFromSeconds(c.command_timeout_s);
  cfg.first_command_due = TimeFromSeconds(c.first_command_due_s);
  for (const Fault& f : s.faults.OfKind(FaultKind::kCommandLinkLoss))
    cfg.link_loss.emplace_back(f.start, f.end);
  auto dev = std::make_unique<actuator::BaseSerialDevice>(cfg);
  set.base = dev.get();
  AddSerialDevice(std::move(dev), c.link, 4096, dir, set);
}

std::vector<std::string> WheelBaseLinks(const Scenario& s) {
  if (!HasWheelBase(s)) return {};
  return {s.closed_loop.link};
}

constexpr std::string_view kWheelBaseNavdKeys[] = {
    "odometry.device",          "odometry.wheel_radius_m",
    "odometry.track_m",         "odometry.counts_per_rev",
    "odometry.origin_lat_deg",  "odometry.origin_lon_deg",
    "odometry.origin_height_m", "odometry.initial_e_m",
    "odometry.initial_n_m",     "odometry.initial_heading_deg"};

// The header's line: the base's wheels and PID rate.
std::string WheelBaseProfile(const Scenario& s) {
  const auto& m = s.closed_loop.motors;
  return ProfileText(
      "ROSArduinoBridge differential-drive base: wheel radius %.3f m, track %.3f m, "
      "%d counts/rev, PID %g Hz",
      m.wheel_radius_m, m.track_m, m.encoder_counts_per_rev, s.closed_loop.pid_rate_hz);
}

}  // namespace

extern const DeviceKind kWheelBaseKind;
const DeviceKind kWheelBaseKind{
    .name = "wheel_base",
    .sections = {},
    .spec = "closed_loop: with channel serial_base (motors, pid_rate_hz; read with the loop)",
    .read = nullptr,
    .seed_stream = 7,
    .build = BuildWheelBase,
    .navd_keys = kWheelBaseNavdKeys,
    .write_navd = WriteWheelBaseNavd,
    .links = WheelBaseLinks,
    .navd_links = nullptr,
    .report_section = "closed_loop",
    .link_role = "",
    .profile = WheelBaseProfile};

}  // namespace hil::harness

#pragma once
/// @file
/// The differential-drive base as a device of the scheduler (closed loop): the ROSArduinoBridge
/// session (base_serial_session.h) on one serial port, driving the wheel motors
/// (wheel_motors.h), which drive the truth vehicle.
///
/// - Host lines (`m L R`, `e`, …) are executed at their emulated arrival time; a speed command
///   takes effect at its arrival plus the motors' `command_latency`.
/// - The device's events lie on the truth's command grid (`grid`, 10 ms): at each it advances the
///   motors and hands their axle speed and yaw rate to the truth for the next grid instant.
/// - Control ticks (every `control_period`, from `control_period` on): a tick at which the last
///   speed command is older than `command_timeout` (or none came yet after the first one was
///   due) counts one missing command. The motors' own watchdog (2 s, the firmware's auto-stop)
///   decides what the base does about it.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/actuator/base_serial_session.h"
#include "hil/firmware_emu/actuator/command_link_loss.h"
#include "hil/firmware_emu/actuator/control_tick_clock.h"
#include "hil/firmware_emu/actuator/wheel_motors.h"
#include "hil/firmware_emu/device.h"

namespace hil::actuator {

struct BaseSerialDeviceConfig {
  std::string name = "base";
  WheelMotorsConfig motors;
  BaseSerialConfig serial;
  Duration grid = std::chrono::milliseconds(10);              ///< the truth's command grid
  Duration control_period = std::chrono::milliseconds(100);   ///< the controller's tick
  Duration command_timeout = std::chrono::milliseconds(300);  ///< a tick's command is missing
  /// Controllers need a solution first: ticks before this time count no missing command.
  Time first_command_due{std::chrono::seconds(3)};
  /// Command-link loss: host bytes arriving in [first, second) never reach the base (a cut cable).
  std::vector<std::pair<Time, Time>> link_loss;
};

/// One control tick's record, for the report's plots and figures.
struct BaseTickRecord {
  Time t{};
  double commanded_yaw_rate_radps = 0;  ///< of the wheel targets last commanded
  double yaw_rate_radps = 0;            ///< of the wheels' speeds
  double speed_mps = 0;
  bool missing = false;
};

using BaseSerialDeviceCounters = ControlTickCounters;  ///< last_command: the latest speed command

class BaseSerialDevice : public Device {
 public:
  explicit BaseSerialDevice(const BaseSerialDeviceConfig& config);

  const std::string& name() const override { return cfg_.name; }
  Time next_event_time() const override { return tick_.next_event_time(); }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int port) const override;
  std::optional<VehicleCommand> TakeVehicleCommand() override;

  const WheelMotors& motors() const { return motors_; }
  const BaseSerialSession& session() const { return session_; }
  const BaseSerialDeviceCounters& counters() const { return counters_; }
  /// Host bytes lost to the command-link loss windows.
  const CommandLinkLoss& link_loss() const { return loss_; }
  /// Called with each control tick's record (e.g. for the report's plots); none are kept here.
  void set_tick_tap(std::function<void(const BaseTickRecord&)> tap) { tick_tap_ = std::move(tap); }

 private:
  void ControlTick(Time t);

  BaseSerialDeviceConfig cfg_;
  WheelMotors motors_;
  BaseSerialSession session_;
  ControlTickClock tick_;
  std::uint64_t seen_motor_commands_ = 0;
  BaseSerialDeviceCounters counters_;
  CommandLinkLoss loss_;
  std::function<void(const BaseTickRecord&)> tick_tap_ = [](const BaseTickRecord&) {};
};

}  // namespace hil::actuator

#pragma once
/// @file
/// Session layer of the base's serial protocol (vectors/base_serial/README.md): the firmware's
/// command loop. Host bytes arrive stamped with their emulated time; each completed line is
/// executed at the arrival time of its CR against the `WheelMotors` and answered with one reply
/// line, ready at the same time (the UART queue of the port paces it). `m L R` sets the targets in
/// encoder ticks per PID frame (`pid_rate_hz`, 30 Hz on ROSArduinoBridge) and feeds the motors'
/// watchdog (auto-stop after 2000 ms without `m`); `m 0 0` stops. Encoder counts are reported as
/// the firmware's 32-bit `long` (wrapping).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/actuator/base_serial_framing.h"
#include "hil/firmware_emu/actuator/wheel_motors.h"
#include "hil/firmware_emu/device.h"

namespace hil::actuator {

struct BaseSerialConfig {
  long baud = 57600;
  double pid_rate_hz = 30.0;
};

struct BaseSerialCounters {
  std::uint64_t lines = 0;
  std::uint64_t invalid = 0;
  std::uint64_t motor_commands = 0;
  std::uint64_t encoder_reads = 0;
};

class BaseSerialSession {
 public:
  BaseSerialSession(const BaseSerialConfig& config, WheelMotors& motors);

  /// Bytes the host wrote, arriving at `t`; replies are appended to `out.serial` (port 0).
  void OnHostBytes(Time t, std::string_view bytes, DeviceOutput& out);

  /// Wheel speed (rad/s) of a target in ticks per PID frame, and back (rounded to nearest).
  double RadpsFromTicksPerFrame(long ticks) const;
  long TicksPerFrameFromRadps(double radps) const;

  const BaseSerialCounters& counters() const { return counters_; }
  std::uint64_t overlong_lines() const { return framer_.overlong_lines(); }

 private:
  std::string Execute(Time t, const std::string& line);

  BaseSerialConfig cfg_;
  WheelMotors& motors_;
  link::CrLineFramer framer_{kMaxBaseLineLength};
  BaseSerialCounters counters_;
};

}  // namespace hil::actuator

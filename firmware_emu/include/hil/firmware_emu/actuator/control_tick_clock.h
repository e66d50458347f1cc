#pragma once
/// @file
/// What the closed-loop actuators (the differential-drive base, the ISOBUS steering device) share:
/// the controller's tick with its missing-command watchdog, and the vehicle command they hand the
/// truth on its grid.
///
/// Each truth instant t (a grid point) an actuator advances its own model to t, then
///   if TickDue(t): CountTick(t, counters) and record the tick;
///   Hold(t, speed, steer or yaw rate): the command drives the truth from the next grid instant on.

#include <cstdint>
#include <optional>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::actuator {

struct ControlTickTiming {
  Duration grid;             ///< the truth's command grid
  Duration control_period;   ///< the controller's tick
  Duration command_timeout;  ///< a tick's command is missing when the latest is older than this
  Time first_command_due;    ///< ticks before it count no missing command (controllers need a fix)
};

struct ControlTickCounters {
  std::uint64_t ticks = 0;
  std::uint64_t missing_commands = 0;
  std::optional<Time> first_missing;  ///< the first tick of the latest run of missing commands
  std::optional<Time> last_command;   ///< arrival of the latest command
};

class ControlTickClock {
 public:
  /// The first tick falls one control period after t = 0.
  explicit ControlTickClock(const ControlTickTiming& timing)
      : timing_(timing), next_tick_(Time{} + timing.control_period) {}

  /// At the truth's instant t: true when the controller's tick falls due (the next one is then one
  /// control period later).
  bool TickDue(Time t);
  /// Counts the tick at t in `c`; true when its command is missing (none yet, or the latest older
  /// than the timeout, once commands are due).
  bool CountTick(Time t, ControlTickCounters& c);
  /// The actuator's state at t drives the truth from the next grid instant on (the first, at t = 0,
  /// from the start: the truth has no input before it), stamped exactly on it: an instant between
  /// grid points (t + 1 ns) would be applied one grid step apart by the truth integrated online and
  /// by its replay for the evaluation (truth.csv). The next event is that grid instant.
  void Hold(Time t, double speed_mps, double steer_or_yaw_rate);
  /// The command held since the last call, once.
  std::optional<VehicleCommand> TakeVehicleCommand();
  Time next_event_time() const { return next_; }

 private:
  ControlTickTiming timing_;
  Time next_tick_;
  Time next_{};
  bool last_missing_ = false;
  std::optional<VehicleCommand> pending_;
};

}  // namespace hil::actuator

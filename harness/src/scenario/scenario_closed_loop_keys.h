#pragma once
// Internal to the harness: the tables of the closed_loop section (scenario_keys.h), read by
// scenario_closed_loop.cc (the isobus channel's steering ECU keys: scenario_closed_loop_isobus.cc).
#include <array>
#include <string_view>

#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness::closed_loop_keys {

using enum KeyType;

inline constexpr std::array<std::string_view, 2> kChannels{"serial_base", "isobus"};
inline constexpr std::array<std::string_view, 2> kTransports{"socketcan", "slcan"};

inline constexpr ScenarioKey kClosedLoop[] = {
    {"channel", kChoice, "", "serial_base", 0, 0,
     "serial_base: the ROSArduinoBridge base of a diff_drive or skid_steer vehicle (wheel speed "
     "commands); isobus: ISO 11783-7 guidance to the steering ECU of a bicycle/tractor",
     kChannels},
    {"link", kString, "", "ttyBASE (isobus: ttyCAN)", 0, 0,
     "the actuator's serial link in the run folder"},
    {"path_file", kString, "", "required", 0, 0,
     "the planned path (vectors/paths/README.md), relative to the scenario file"},
    {"controller", kString, "", "required", 0, 0,
     "the controller's shell command; {guidanced}, {path_file}, {nav_nmea}, {origin}, {run_dir} "
     "and the link names are substituted"},
    {"control_period_s", kNumber, "s", "0.1", 0.01, 10, "the controller's tick"},
    {"command_timeout_s", kNumber, "s", "0.3", 0.01, 60,
     "a tick whose last command is older counts one missing command"},
    {"first_command_due_s", kNumber, "s", "3", 0, 600,
     "ticks before this count no missing command"},
    {"start_enu_m", kPoint, "m", "[0, 0]", 0, 0,
     "where the vehicle's reference point starts [east, north]"},
    {"start_heading_deg", kNumber, "deg", "0", -360, 360,
     "its heading at the start, clockwise from north"},
    {"initial_speed_mps", kNumber, "m/s", "0", 0, 10,
     "the vehicle rolls straight at this speed when the run starts"},
    {"actuator", kMapping, "", "the defaults below", 0, 0,
     "serial_base: the wheel motors (closed_loop.actuator); isobus: the steering ECU "
     "(vectors/scenarios/closed_loop/README.md)"},
    {"transport", kChoice, "", "socketcan", 0, 0,
     "isobus: the scenario's can bus, or a serial CAN adapter (slcan) on `link`", kTransports},
    {"speed_mps", kNumber, "m/s", "by the ECU", 0, 15, "isobus: the vehicle's set speed"},
    {"slcan_baud", kInteger, "Bd", "115200", 1200, 4000000, "isobus, slcan: the adapter's baud"},
    {"fault_window_s", kNumber, "s", "10", 0, 3600,
     "tracking.faults scores each fault to this long after its end"},
    {"pass_to_pass", kMapping, "", "the defaults below", 0, 0,
     "the ISO 12188-2 style pass-to-pass evaluation (closed_loop.pass_to_pass)"},
};

// Where the base's figures come from: ROSArduinoBridge's firmware for its protocol's timing
// (vectors/base_serial/README.md), ours for the motors (wheel_motors.h cites no source).
inline constexpr std::string_view kBaseOurs = "ours (wheel_motors.h cites no source)";
inline constexpr std::string_view kSrcAutoStop =
    "ROSArduinoBridge's AUTO_STOP_INTERVAL, 2000 ms (hbrobotics/ros_arduino_bridge "
    "ROSArduinoBridge.ino; shared/reference/seeds_001_003.md C, vectors/base_serial/README.md)";
inline constexpr std::string_view kSrcPidRate =
    "ROSArduinoBridge's PID frame rate, 30 Hz (hbrobotics/ros_arduino_bridge ROSArduinoBridge.ino; "
    "shared/reference/seeds_001_003.md C, vectors/base_serial/README.md)";

inline constexpr ScenarioKey kActuator[] = {
    {"wheel_radius_m", kNumber, "m", "0.1", 0.01, 2, "the wheels' (sprockets') radius", kNoChoices,
     kAnyRange, kBaseOurs},
    {"encoder_counts_per_rev", kInteger, "", "1200", 1, 1 << 20,
     "quadrature counts per wheel revolution", kNoChoices, kAnyRange, kBaseOurs},
    {"max_wheel_speed_radps", kNumber, "rad/s", "20", 0.1, 500, "the wheels' speed limit",
     kNoChoices, kAnyRange, kBaseOurs},
    {"max_wheel_accel_radps2", kNumber, "rad/s²", "30", 0.1, 1e4, "the wheels' acceleration limit",
     kNoChoices, kAnyRange, kBaseOurs},
    {"time_constant_s", kNumber, "s", "0.08", 0.001, 10, "the speed loop's first-order lag",
     kNoChoices, kAnyRange, kBaseOurs},
    {"slip", kPoint, "", "[0, 0]", 0, 0,
     "[left, right]: fraction of the tyre speed lost, each in [0, 1) (ground speed = ω·r·(1 − "
     "slip)); a skid_steer's turning slip is vehicle.icr_expansion"},
    {"command_latency_s", kNumber, "s", "0.005", 0, 5, "a command acts this long after its arrival",
     kNoChoices, kAnyRange, kBaseOurs},
    {"watchdog_timeout_s", kNumber, "s", "2", 0.01, 60,
     "no command for this long stops the wheels (ROSArduinoBridge's AUTO_STOP_INTERVAL)",
     kNoChoices, kAnyRange, kSrcAutoStop},
    {"pid_rate_hz", kNumber, "Hz", "30", 1, 1000, "ROSArduinoBridge's PID frame rate", kNoChoices,
     kAnyRange, kSrcPidRate},
};

// The isobus channel's steering ECU (`actuator:` of channel isobus; steering_ecu.h). Its defaults
// are SteeringEcuConfig's, the steering's the vehicle's.
inline constexpr std::string_view kEcuOurs = "ours (steering_ecu.h cites no source)";
inline constexpr ScenarioKey kSteeringEcu[] = {
    {"max_steer_deg", kNumber, "deg", "vehicle.max_steer_deg", 1, 60,
     "± road-wheel angle limit (limit status when a command asks for more)"},
    {"max_steer_rate_dps", kNumber, "deg/s", "vehicle.max_steer_rate_dps", 1, 1000,
     "the road wheels' slew limit"},
    {"time_constant_s", kNumber, "s", "vehicle.steer_lag_s", 0.001, 10,
     "the road wheels' first-order lag"},
    {"deadband_deg", kNumber, "deg", "0.05", 0, 5,
     "the valve does not act on a smaller position error", kNoChoices, kAnyRange, kEcuOurs},
    {"command_latency_s", kNumber, "s", "0.02", 0, 5, "a command acts this long after its arrival",
     kNoChoices, kAnyRange, kEcuOurs},
    {"watchdog_timeout_s", kNumber, "s", "0.3", 0.01, 60,
     "engaged and no valid command for this long: exit reason 5 (remote command timeout)",
     kNoChoices, kAnyRange, kEcuOurs},
    {"status_period_s", kNumber, "s", "0.1", 0.01, 10,
     "period of Guidance Machine Info (0xAC00) and Wheel-based Speed and Distance (0xFE48)",
     kNoChoices, kAnyRange, kEcuOurs},
    {"ecu_address", kInteger, "", "28 (0x1C)", 0, 253, "the ECU's own J1939 source address",
     kNoChoices, kAnyRange, kEcuOurs},
    {"guidance_address", kInteger, "", "128 (0x80)", 0, 253,
     "the only source address whose commands are accepted", kNoChoices, kAnyRange, kEcuOurs},
    {"min_engage_speed_mps", kNumber, "m/s", "0", 0, 50,
     "below this speed the ECU exits (reason 23; 0: no lower limit)"},
    {"max_engage_speed_mps", kNumber, "m/s", "15", 0.1, 50,
     "above this speed the ECU exits (reason 24)", kNoChoices, kAnyRange, kEcuOurs},
    {"center_on_disengage", kBool, "", "false", 0, 0,
     "true: the wheels return to centre on disengaging; false: they stay (hydraulic hold)"},
};

inline constexpr ScenarioKey kPassToPass[] = {
    {"window_s", kNumber, "s", "900", 1, 86400, "the window pass-to-pass accuracy is quoted over"},
    {"margin_m", kNumber, "m", "10", 0, 1e4, "left out at each end of a pass (settling)"},
    {"max_angle_deg", kNumber, "deg", "5", 0, 45,
     "two straight segments this parallel are adjacent passes"},
};

}  // namespace hil::harness::closed_loop_keys

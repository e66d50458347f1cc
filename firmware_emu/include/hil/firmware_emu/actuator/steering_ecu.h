#pragma once
/// @file
/// The emulated ISOBUS steering ECU (vectors/isobus/README.md, "The emulated steering ECU"): it
/// receives Guidance System Command (0xAD00), steers the road wheels and reports Guidance Machine
/// Info (0xAC00) and Wheel-based Speed and Distance (0xFE48).
///
/// - A command takes effect at its arrival time plus `command_latency`.
/// - "Intended to steer" engages, "not intended to steer" disengages; after any exit (watchdog,
///   out-of-range command, speed, command status error) the ECU asks for a reset (request reset
///   command status = 1) and engages again only after a "not intended to steer".
/// - The road-wheel angle follows the target with a first-order lag (τ), a rate limit, the ±limit
///   (limit status 2 high / 3 low when the command asks for more) and a position deadband.
/// - Watchdog: engaged and no valid command received for `command_timeout` ⇒ exit reason 5 (remote
///   command timeout) at exactly last arrival + timeout, counted and recorded.
/// - Bad frames are refused and counted: wrong DLC and unknown source are ignored (they do not feed
///   the watchdog); a curvature raw value above 64255 disengages with exit reason 6 (remote command
///   out of range).
/// Angles and curvature are in the ISOBUS sign (positive = right); `curvature_left_per_m()` gives
/// the ENU/FLU sign the truth uses. Pure and deterministic: time only through `hil::Time`.

#include <array>
#include <cstdint>

#include "hil/firmware_emu/actuator/isobus_guidance.h"
#include "hil/firmware_emu/device.h"

namespace hil::actuator {

/// Exit reason codes the ECU uses (ISO 11783-7 Guidance Machine Info byte 4 bits 0–5).
enum class ExitReason : std::uint8_t {
  kAllClear = 0,
  kRemoteCommandTimeout = 5,
  kRemoteCommandOutOfRange = 6,
  kSpeedTooLow = 23,
  kSpeedTooHigh = 24,
  kError = 62,
};

struct SteeringEcuConfig {
  std::uint8_t source_address = 0x1C;  ///< the ECU's own address
  std::uint8_t priority = 3;
  std::array<std::uint8_t, 4> accepted_sources{0x80, 0x80, 0x80, 0x80};  ///< guidance addresses
  double wheelbase_m = 2.5;
  double max_steer_deg = 35.0;       ///< ± road-wheel angle limit
  double max_steer_rate_dps = 40.0;  ///< slew limit
  double time_constant_s = 0.15;     ///< first-order lag
  double deadband_deg = 0.05;        ///< the valve does not act on a smaller position error
  Duration command_latency = std::chrono::milliseconds(20);
  Duration command_timeout = std::chrono::milliseconds(300);
  Duration status_period = std::chrono::milliseconds(100);
  double min_engage_speed_mps = 0.0;   ///< exit 23 below (0: no lower limit)
  double max_engage_speed_mps = 15.0;  ///< exit 24 above
  bool center_on_disengage = false;    ///< false: the wheels stay where they are (hydraulic hold)
};

struct SteeringEcuCounters {
  std::uint64_t commands_accepted = 0;
  std::uint64_t wrong_length = 0;
  std::uint64_t unknown_source = 0;
  std::uint64_t out_of_range = 0;
  std::uint64_t not_addressed = 0;   ///< for another ECU (ignored silently, counted)
  std::uint64_t queue_overflow = 0;  ///< more commands in flight than the latency queue holds
  std::uint64_t watchdog_trips = 0;
  std::uint64_t engagements = 0;
  Time last_watchdog_trip{};  ///< valid when watchdog_trips > 0
};

class SteeringEcu {
 public:
  explicit SteeringEcu(const SteeringEcuConfig& config);

  /// A frame received at emulated time `t` (≥ the ECU's time; it advances there first with the
  /// speed of the last `AdvanceTo`). Frames of other PGNs are ignored.
  void OnFrame(Time t, const CanFrame& frame);
  /// Advances to `t` with the vehicle's wheel-based speed held over the interval.
  void AdvanceTo(Time t, double speed_mps);

  Time now() const { return now_; }
  bool engaged() const { return engaged_; }
  double steer_angle_rad() const { return delta_rad_; }  ///< actual, positive right
  double target_steer_angle_rad() const { return target_rad_; }
  /// Actual path curvature tan(δ)/L in the ENU/FLU sign (positive = turning left), 1/m.
  double curvature_left_per_m() const;
  GuidanceMachineInfo machine_info() const;
  const SteeringEcuCounters& counters() const { return counters_; }
  ExitReason exit_reason() const { return exit_reason_; }

  /// When the next Machine Info / Wheel-based Speed pair is due.
  Time next_status_time() const { return next_status_; }
  /// Appends the pair due at `next_status_time()` (which must be ≤ the ECU's time) and schedules
  /// the next one. `distance_m` is the wheel-based distance travelled.
  void EmitStatus(double speed_mps, double distance_m, DeviceOutput& out);

 private:
  struct Pending {
    Time t_effect{};
    GuidanceSystemCommand cmd;
  };
  bool SourceAccepted(std::uint8_t sa) const;
  void Integrate(double dt_s);
  void Apply(const GuidanceSystemCommand& cmd);
  void Exit(ExitReason reason);
  void CheckSpeed();

  SteeringEcuConfig cfg_;
  Time now_{};
  double speed_mps_ = 0;
  double delta_rad_ = 0;
  double target_rad_ = 0;
  std::uint8_t limit_status_ = 0;
  bool engaged_ = false;
  bool reset_required_ = false;
  ExitReason exit_reason_ = ExitReason::kAllClear;
  Time last_valid_arrival_{};
  Time next_status_{};
  std::array<Pending, 16> queue_{};
  int queue_head_ = 0;
  int queue_size_ = 0;
  SteeringEcuCounters counters_;
};

}  // namespace hil::actuator

#pragma once
/// @file
/// The emulated wheel motors of a differential-drive base (vectors/base_serial/README.md, "The
/// emulated base"): two wheels, each with a speed loop modelled as a first-order lag with an
/// acceleration limit and a ± speed limit, a quadrature encoder on the wheel shaft (integer counts,
/// floor of the shaft angle), and slip between tyre and ground (ground speed = ω·r·(1 − slip)).
/// A command takes effect at its arrival time plus `command_latency`. The watchdog stops both
/// wheels (target 0, still through the acceleration limit) when no speed command arrived for
/// `command_timeout`; trips are counted and the time recorded. Pure and deterministic.

#include <array>
#include <cstdint>
#include <vector>

#include "hil/firmware_emu/actuator/wheel_motor_faults.h"
#include "hil/firmware_emu/sim_time.h"

namespace hil::actuator {

inline constexpr int kLeftWheel = 0;
inline constexpr int kRightWheel = 1;

struct WheelMotorsConfig {
  double wheel_radius_m = 0.1;
  double track_m = 0.5;  ///< distance between the wheels' contact points
  /// A skid-steered base: the wheels' (tracks') instantaneous centres of rotation lie χ·track
  /// apart, so the yaw rate is (v_r − v_l) / (χ·track) (harness/truth vehicle.h, skid_steer);
  /// 1 for a differential drive.
  double icr_expansion = 1.0;
  int encoder_counts_per_rev = 1200;  ///< quadrature counts per wheel revolution
  double max_wheel_speed_radps = 20.0;
  double max_wheel_accel_radps2 = 30.0;
  double time_constant_s = 0.08;
  std::array<double, 2> slip{0.0, 0.0};  ///< fraction of the tyre speed lost, left and right
  Duration command_latency = std::chrono::milliseconds(5);
  Duration command_timeout = std::chrono::milliseconds(2000);
  /// Both wheels turn at this speed at t = 0 (a base already rolling when the run starts); the
  /// watchdog counts from the first command.
  double initial_wheel_speed_radps = 0.0;
  /// Scripted faults (wheel_motor_faults.h): latency and jitter, saturation, a stuck drive.
  std::vector<WheelMotorFault> faults;
  std::uint64_t fault_seed = 0;  ///< the jitter's draws
};

struct WheelMotorsCounters {
  std::uint64_t commands = 0;
  std::uint64_t saturated_commands = 0;  ///< beyond ± the speed limit at their arrival
  double saturated_s = 0;  ///< time a wheel's target was beyond the speed limit (clamped)
  std::uint64_t queue_overflow = 0;
  std::uint64_t watchdog_trips = 0;
  Time last_watchdog_trip{};  ///< valid when watchdog_trips > 0
};

class WheelMotors {
 public:
  explicit WheelMotors(const WheelMotorsConfig& config);

  /// Wheel speed targets (rad/s, positive = forward) received at `t` (≥ the motors' time).
  void Command(Time t, double left_radps, double right_radps);
  /// Advances both wheels to `t`.
  void AdvanceTo(Time t);
  /// Sets both encoder counts to zero (at the motors' current time).
  void ResetEncoders();

  Time now() const { return now_; }
  double wheel_speed_radps(int wheel) const { return speed_radps_[wheel]; }
  /// The speed last commanded for the wheel, in effect now (0 after a trip); the loop steers to
  /// it clamped to the speed limit.
  double target_speed_radps(int wheel) const { return target_radps_[wheel]; }
  double ground_speed_mps(int wheel) const;
  /// Forward speed (m/s) and yaw rate (rad/s, positive = left) of the midpoint of the axle (the
  /// yaw rate through `icr_expansion`).
  double body_speed_mps() const;
  double body_yaw_rate_radps() const;
  std::int64_t encoder_count(int wheel) const;
  bool stopped_by_watchdog() const { return tripped_; }
  const WheelMotorsCounters& counters() const { return counters_; }
  const WheelMotorsConfig& config() const { return cfg_; }
  const WheelMotorFaults& faults() const { return faults_; }

 private:
  struct Pending {
    Time t_effect{};
    std::array<double, 2> target_radps{};
  };
  void Integrate(double dt_s);

  WheelMotorsConfig cfg_;
  Time now_{};
  std::array<double, 2> speed_radps_{};
  std::array<double, 2> target_radps_{};
  std::array<double, 2> angle_rad_{};  ///< shaft angle since the last encoder reset
  Time last_command_{};
  bool tripped_ = false;
  bool ever_commanded_ = false;
  std::array<Pending, 16> queue_{};
  int queue_head_ = 0;
  int queue_size_ = 0;
  Time last_effect_{};  ///< of the latest command queued (the line keeps its order)
  WheelMotorsCounters counters_;
  WheelMotorFaults faults_;
};

}  // namespace hil::actuator

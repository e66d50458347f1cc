#pragma once
/// @file
/// Faults of the emulated wheel motors in a closed-loop run (the scenario's `faults:` list,
/// vectors/scenarios/closed_loop/README.md), each active on [start, end):
/// - command latency and jitter: a speed command arriving in the window takes effect `latency`
///   plus a uniform draw in [0, `jitter`) later than it would (the draw is a hash of the seed and
///   the command's index: the same run gives the same delays whatever the byte chunking). The
///   serial line keeps its order: a command never takes effect before the one sent ahead of it.
/// - saturation: the drive's speed limit drops to `max_wheel_speed_radps` (a current limit, a
///   low battery); the wheels' targets are clamped to it while it lasts.
/// - stuck: the drive holds its output: both wheels keep the speed they had at `start` until
///   `end`, whatever is commanded; afterwards they follow the latest command again.
/// Pure and deterministic; counted per fault.

#include <cstdint>
#include <vector>

#include "hil/firmware_emu/sim_time.h"

namespace hil::actuator {

struct WheelMotorFault {
  enum class Kind { kCommandLatency, kSaturation, kStuck };
  Kind kind = Kind::kCommandLatency;
  Time start{};
  Time end{};
  Duration latency{};                ///< kCommandLatency: added to each command in the window
  Duration jitter{};                 ///< kCommandLatency: plus uniform [0, jitter)
  double max_wheel_speed_radps = 0;  ///< kSaturation: the limit in the window
  std::size_t timeline_index = 0;    ///< the scenario's fault this is (for the report)
  bool ActiveAt(Time t) const { return t >= start && t < end; }
};

/// What one fault did.
struct WheelMotorFaultCounters {
  /// latency: commands delayed; saturation: commands beyond the limit; stuck: commands that
  /// arrived while the drive held its output.
  std::uint64_t events = 0;
  Duration added_latency_total{};  ///< latency: the sum of the delays added
  Duration added_latency_max{};    ///< latency: the largest delay added
  double clamped_s = 0;            ///< saturation: time a wheel's target was clamped
  double held_s = 0;               ///< stuck: time the output was held
};

class WheelMotorFaults {
 public:
  WheelMotorFaults() = default;
  WheelMotorFaults(std::vector<WheelMotorFault> faults, std::uint64_t seed);

  /// The delay added to command number `index` (0, 1, …) arriving at `t`; counted.
  Duration AddedLatency(Time t, std::uint64_t index);
  /// The speed limit at `t`: `nominal`, or the lowest limit of the saturation faults active.
  double SpeedLimit(Time t, double nominal) const;
  bool Stuck(Time t) const;
  /// The first start or end of a fault after `t` (Time::max() when none).
  Time NextBoundaryAfter(Time t) const;
  /// A command arrived at `t`; `beyond_limit`: a target exceeded SpeedLimit(t).
  void NoteCommand(Time t, bool beyond_limit);
  /// [t, t + dt_s) went by with a target clamped (`clamped`) and/or the output held.
  void NoteInterval(Time t, double dt_s, bool clamped);

  bool empty() const { return faults_.empty(); }
  const std::vector<WheelMotorFault>& faults() const { return faults_; }
  /// One per fault, in the order of faults().
  const std::vector<WheelMotorFaultCounters>& counters() const { return counters_; }

 private:
  std::vector<WheelMotorFault> faults_;
  std::vector<WheelMotorFaultCounters> counters_;
  std::uint64_t seed_ = 0;
};

}  // namespace hil::actuator

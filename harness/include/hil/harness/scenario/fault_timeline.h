#pragma once
/// @file
/// The scenario's global fault timeline (`faults:` in the scenario file): what goes wrong, when.
///
///   faults:
///     - {kind: gnss_outage, start_s: 40, end_s: 55}
///     - {kind: gnss_data_gap, start_s: 60, end_s: 65}
///     - {kind: gnss_glitch, start_s: 70, end_s: 72, north_m: 8, east_m: -3}
///     - {kind: byte_corruption, start_s: 10, end_s: 20, probability: 0.001, link: ttyGPS}
///     - {kind: frame_drop, start_s: 30, end_s: 35, probability: 0.5}
///     - {kind: mcu_reset, start_s: 90}
///     - {kind: baud_mismatch, start_s: 100, end_s: 110, baud: 4800, link: ttyGPS}
///     - {kind: byte_corruption, start_s: 10, end_s: 20, bit_error_rate: 1e-4, link: ttyGPS}
///     - {kind: frame_duplicate, start_s: 30, end_s: 35, probability: 0.2, link: ttyIMU}
///     - {kind: frame_truncate, start_s: 30, end_s: 35, probability: 0.2, link: ttyGPS}
///     - {kind: can_reorder, start_s: 30, end_s: 35, probability: 0.5}
///     - {kind: gnss_overload, start_s: 40, end_s: 60}
///     - {kind: controller_stop, start_s: 15}                          # closed loop
///     - {kind: command_link_loss, start_s: 15, end_s: 18}
///     - {kind: command_latency, start_s: 10, end_s: 40, latency_s: 0.15, jitter_s: 0.1}
///     - {kind: actuator_saturation, start_s: 20, end_s: 30, max_wheel_speed_radps: 4}
///     - {kind: actuator_stuck, start_s: 20, end_s: 23}
///
/// mcu_reset takes an optional end_s: the MCU is silent from start_s to end_s (its reboot time;
/// without end_s the mcu section's reboot time). byte_corruption takes either `probability` (per
/// byte: one random bit flipped) or `bit_error_rate` (every bit flipped independently).
/// Who applies what: the GNSS device model applies gnss_outage, gnss_data_gap, gnss_glitch and
/// gnss_overload (its UART transmit buffer then overflows and drops whole messages), the MCU model
/// mcu_reset; the scheduler applies byte_corruption, frame_drop, frame_duplicate, frame_truncate
/// and baud_mismatch (what the host's UART receives) to whole serial messages and can_reorder to
/// CAN frames (ByteFaultInjector in byte_faults.h). Every injection is counted per fault
/// (fault_record.h). The evaluator reads the outages and each fault's recovery time.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/sim_time.h"

namespace hil::harness {

class YamlReader;

enum class FaultKind {
  kGnssOutage,
  kGnssDataGap,
  kGnssGlitch,
  kByteCorruption,
  kFrameDrop,
  kMcuReset,
  kBaudMismatch,
  kFrameDuplicate,  ///< a serial message sent twice (with `probability`)
  kFrameTruncate,   ///< a serial message cut short at a random byte (with `probability`)
  kCanReorder,      ///< two consecutive CAN frames of one device swap places (with `probability`)
  kGnssOverload,  ///< the receiver outputs every message it knows: more bytes than its baud carries
  kControllerStop,   ///< closed loop: the controller process is killed (SIGKILL) at start_s
  kCommandLinkLoss,  ///< closed loop: the controller's bytes do not reach the actuator in [start,
                     ///< end)
  /// closed loop, the actuator (wheel_motor_faults.h): commands arriving in [start, end) act
  /// `latency_s` plus a seeded uniform [0, `jitter_s`) late
  kCommandLatency,
  kActuatorSaturation,  ///< closed loop: the drive's speed limit is `max_wheel_speed_radps`
  kActuatorStuck,       ///< closed loop: the drive holds its output from start to end
};

/// The scenario-file name of a kind ("gnss_outage", …).
const char* FaultKindName(FaultKind kind);

/// One fault, active on [start, end) (an instantaneous fault such as mcu_reset has end == start).
struct Fault {
  FaultKind kind = FaultKind::kGnssOutage;
  Time start{};
  Time end{};
  std::string link;  ///< the link it applies to ("" = every link); byte faults, baud
  std::map<std::string, double> params;  ///< kind-specific numbers (probability, north_m, baud, …)
  /// A parameter, or `fallback` when the scenario did not give it.
  double Param(const std::string& key, double fallback) const;
  bool ActiveAt(Time t) const { return t >= start && t < end; }
};

struct FaultTimeline {
  std::vector<Fault> faults;  ///< in file order
  /// Faults of one kind, sorted by start time.
  std::vector<Fault> OfKind(FaultKind kind) const;
  /// The first fault of `kind` active at `t` on `link` (or on every link), if any.
  std::optional<Fault> ActiveAt(FaultKind kind, Time t, const std::string& link = "") const;
  bool empty() const { return faults.empty(); }
};

/// Reads the `faults` list. Each element is checked: known kind, the keys that kind takes,
/// 0 ≤ start_s < end_s ≤ duration_s (end_s omitted only for mcu_reset), parameter ranges.
/// @throws ScenarioError naming file, line and field.
FaultTimeline ReadFaultTimeline(const YamlReader& list, double duration_s);

}  // namespace hil::harness

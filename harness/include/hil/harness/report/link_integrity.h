#pragma once
/// @file
/// What the estimator says it received, against what the run sent (issue 40.6: navd once counted
/// 127 NMEA checksum errors, 520 IMU CRC errors and 3786 garbage bytes while the captures were
/// clean, and the report said nothing).
///
/// navd counts in its `health` object (navd_health.h) every sentence or frame it could not decode,
/// every byte outside one, and on the IMU link every sequence number it missed or saw twice. On a
/// link the run sent intact, each of these counters must stay 0: a byte lost, added or changed
/// between the run's capture and the estimator's read shows in them. A link's counters are
/// excused only where the scenario damages its bytes on purpose (byte_corruption, frame_drop,
/// frame_truncate, frame_duplicate, baud_mismatch on that link or on every link; gnss_overload on
/// a GNSS link, mcu_reset on the IMU link: a reset cuts a frame), and in real time the counts at
/// the estimator's first solution (it opened its ports while the devices were talking and may
/// have come in mid-message, as on any real line).
///
/// report.json gains `"link_integrity": [{"role", "links", "bytes_sent", "bytes_dropped",
/// "estimator_counters": {name: value}, "excused_by", "intact"}]`, and every link found damaged
/// (or whose bytes the run itself dropped while the estimator had the port open) is a problem: the
/// run does not pass.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hil/harness/faults/fault_report.h"
#include "hil/harness/scenario/fault_timeline.h"

namespace hil::harness {

/// One link the estimator reads, as the run sent it.
struct LinkSent {
  std::string link;                 ///< its name (ttyGPS)
  std::string role;                 ///< "gnss" or "imu": which of navd's counters speak for it
  std::uint64_t bytes_sent = 0;     ///< bytes the capture records as written to the host
  std::uint64_t bytes_dropped = 0;  ///< bytes the run dropped while the host had the port open
};

/// One role's verdict (the GNSS receivers share navd's gnss_* counters).
struct LinkIntegrity {
  std::string role;
  std::vector<std::string> links;
  std::uint64_t bytes_sent = 0, bytes_dropped = 0;
  std::map<std::string, double> estimator_counters;  ///< navd's, less the start-up baseline
  std::vector<std::string> excused_by;               ///< fault kinds that damage these bytes
  bool intact = true;
  std::string problem;  ///< empty when intact
};

/// navd's counters that speak for a role's link ("gnss": checksum errors, malformed sentences,
/// garbage bytes; "imu": CRC errors, bad headers, garbage bytes, sequence gaps, repeated frames).
const std::vector<std::string>& EstimatorLinkCounters(const std::string& role);

/// Compares `health` (the estimator's last counters; `baseline`: those to subtract, e.g. at its
/// first solution in real time, else empty) with what was sent. Without a health object (an
/// estimator other than navd) only the run's own drops are judged.
std::vector<LinkIntegrity> CheckLinkIntegrity(const std::vector<LinkSent>& sent,
                                              const EstimatorHealth& health,
                                              const std::map<std::string, double>& baseline,
                                              const FaultTimeline& faults);

nlohmann::json LinkIntegrityJson(const std::vector<LinkIntegrity>& links);

}  // namespace hil::harness

#pragma once
/// @file
/// Closed loop on the isobus channel: what the steering ECU and its transport saw (report.json
/// `closed_loop.steering_ecu`; vectors/scenarios/closed_loop/README.md).

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace hil::actuator {
class IsobusSteeringDevice;
}

namespace hil::harness {

struct SteeringEcuReport {
  std::string transport;  ///< "socketcan" or "slcan"
  std::uint64_t frames_from_controller = 0, frames_lost = 0;
  std::uint64_t commands_accepted = 0, wrong_length = 0, unknown_source = 0, out_of_range = 0;
  std::uint64_t not_addressed = 0, engagements = 0, watchdog_trips = 0;
  bool engaged = false;                      ///< at the end of the run
  int exit_reason_code = 0;                  ///< the last exit reason (0 all clear)
  std::string exit_reason;                   ///< its name
  double commanded_steer_rms_error_deg = 0;  ///< actual − target road-wheel angle over the ticks
  /// slcan: the adapter's session
  std::uint64_t slcan_records = 0, slcan_refused = 0, slcan_frames_to_host = 0;
  std::uint64_t slcan_dropped_closed = 0, slcan_opens = 0;
  int slcan_bitrate_bps = 0;
};

/// The report of a run's steering ECU.
SteeringEcuReport MakeSteeringEcuReport(const actuator::IsobusSteeringDevice& device);
nlohmann::json SteeringEcuJson(const SteeringEcuReport& r);
/// Its figures for the criteria, `closed_loop.steering_ecu.*` (engaged as 0/1, exit_reason_code,
/// engagements, watchdog_trips, frames_lost, wrong_length, unknown_source, out_of_range); none
/// without an ECU.
void AddSteeringEcuMetrics(const std::optional<SteeringEcuReport>& r,
                           std::map<std::string, std::optional<double>>& table);

}  // namespace hil::harness

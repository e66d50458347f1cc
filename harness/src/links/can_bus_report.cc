#include "hil/harness/links/can_bus_report.h"

#include <string>

namespace hil::harness {

nlohmann::json CanBusJson(const CanBusReport& c) {
  nlohmann::json per_pgn = nlohmann::json::object();
  for (const auto& [pgn, n] : c.received_per_pgn) per_pgn[std::to_string(pgn)] = n;
  return {{"interface", c.interface},
          {"frames_sent", c.frames_sent},
          {"frames_received", c.frames_received},
          {"rx_queue_drops", c.rx_queue_drops},
          {"send_queue_full", c.send_queue_full},
          {"send_failures", c.send_failures},
          {"error_frames", c.error_frames},
          {"lost", c.lost()},
          {"received_per_pgn", per_pgn}};
}

}  // namespace hil::harness

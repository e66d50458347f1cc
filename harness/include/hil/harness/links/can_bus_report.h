#pragma once
/// @file
/// The CAN bus of a run in report.json (`"can"`): frames each way and every loss.

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace hil::harness {

struct CanBusReport {
  std::string interface;
  std::uint64_t frames_sent = 0;      ///< the devices' frames put on the bus
  std::uint64_t frames_received = 0;  ///< frames others (the estimator) put on the bus, read back
  std::uint64_t rx_queue_drops = 0;   ///< frames our socket's receive queue dropped (SO_RXQ_OVFL)
  std::uint64_t send_queue_full = 0, send_failures = 0;  ///< frames that never left
  std::uint64_t error_frames = 0;
  std::map<std::uint32_t, std::uint64_t>
      received_per_pgn;  ///< output n2k_socketcan: navd's frames per PGN
  std::uint64_t lost() const { return rx_queue_drops + send_queue_full + send_failures; }
};

nlohmann::json CanBusJson(const CanBusReport& c);

}  // namespace hil::harness

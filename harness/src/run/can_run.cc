#include "hil/harness/run/can_run.h"

#include <stdexcept>
#include <string>

namespace hil::harness {

void CheckCanRunMode(const Scenario& s, const RunOptions& opt) {
  if (!s.can.imu_to_estimator || opt.emulate_only || opt.mode != RunMode::kVirtual) return;
  throw std::runtime_error(
      "scenario " + s.name +
      " feeds the estimator's IMU over CAN (can: imu_to_estimator): J1939 IMU frames carry no "
      "sample time, the estimator stamps them on arrival, so run it with --mode realtime or "
      "--mode scaled --speed N (virtual mode sends every frame at once)");
}

void AddCanBusReport(const CanEndpoint& bus,
                     const std::map<std::uint32_t, std::uint64_t>& received_per_pgn,
                     RunReport& report) {
  const link::CanPortStats& st = bus.stats();
  CanBusReport c;
  c.interface = bus.iface();
  c.frames_sent = st.frames_sent;
  c.frames_received = st.frames_received;
  c.rx_queue_drops = st.rx_queue_drops;
  c.send_queue_full = st.send_queue_full;
  c.send_failures = st.send_failures;
  c.error_frames = st.error_frames;
  c.received_per_pgn = received_per_pgn;
  if (c.lost() > 0) {
    report.problems.push_back("the CAN bus " + c.interface + " lost " + std::to_string(c.lost()) +
                              " frame(s): " + std::to_string(c.rx_queue_drops) +
                              " dropped by the receive queue, " +
                              std::to_string(c.send_queue_full + c.send_failures) + " never sent");
  }
  report.can = c;
}

}  // namespace hil::harness

#pragma once
/// @file
/// What a run does for its CAN bus beyond sending and capturing frames (can_endpoint.h):
/// - the run mode an IMU on CAN needs: J1939 IMU frames carry no sample time, so the estimator
///   stamps them on arrival (kernel receive time, mapped onto GPS time by the HIL_TIME_PULSE
///   frames). In virtual mode the harness puts every frame on the bus as soon as it exists, so
///   arrival times mean nothing (and vcan, having no back-pressure, would overflow the estimator's
///   socket): such a scenario runs in real-time or scaled mode, where each frame leaves at its
///   time;
/// - the bus summary of report.json, with losses made a problem of the run (a lossy bus invalidates
/// it).

#include <cstdint>
#include <map>

#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/report/report.h"
#include "hil/harness/run/run.h"

namespace hil::harness {

/// @throws std::runtime_error when the scenario feeds the estimator's IMU over CAN in virtual mode.
void CheckCanRunMode(const Scenario& scenario, const RunOptions& options);
/// Fills report.can from the endpoint's counters and adds a problem for every lost frame.
void AddCanBusReport(const CanEndpoint& bus,
                     const std::map<std::uint32_t, std::uint64_t>& received_per_pgn,
                     RunReport& report);

}  // namespace hil::harness

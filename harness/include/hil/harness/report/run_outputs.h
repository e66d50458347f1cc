#pragma once
/// @file
/// Files of the run folder besides the reports: truth.csv, gnss_fixes.csv, schedule_error.json
/// (navd.conf: devices/navd_conf.h).

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json_fwd.hpp>

#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/core/machine_load.h"
#include "hil/harness/core/quantile_sketch.h"
#include "hil/harness/core/truth_table.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// Closed loop: the FIFO in the run folder into which navd writes its NMEA 0183 solution for the
/// controller ([output] nmea_device), substituted as {nav_nmea} in the controller's command.
inline constexpr const char* kNavNmeaFifo = "nav.nmea";

/// Truth at 10 Hz as CSV; returns the horizontal track (t, east, north) for the plots.
void WriteTruthCsv(const Scenario& s, const std::string& path, std::vector<double>& t_s,
                   std::vector<Eigen::Vector2d>& en_m);
/// The same from a table that holds the times TruthCsvTimes(s) gives.
void WriteTruthCsv(const TruthTable& truth, const Scenario& s, const std::string& path,
                   std::vector<double>& t_s, std::vector<Eigen::Vector2d>& en_m);
/// truth.csv's header line, and its line of the sample `x` at `t` (written as the run goes:
/// harness/run/run_scoring.h).
void AppendTruthCsvHeader(std::string& text);
void AppendTruthCsvRow(std::string& text, Time t, const TruthSample& x);
/// truth.csv's time step.
inline constexpr Duration kTruthCsvStep = std::chrono::milliseconds(100);
/// The times of truth.csv: every 100 ms from 0 to the scenario's end.
std::vector<Time> TruthCsvTimes(const Scenario& s);

/// gnss_fixes.csv, written as the run goes: the header line, then one line per raw GNSS fix.
void WriteFixCsvHeader(std::ostream& out);
void WriteFixCsvLine(std::ostream& out, const gnss::GnssFix& fix);

/// What schedule_error.json reports of a run, read from its devices and links (which outlive it):
/// each link's schedule errors (µs: wall time sent − scheduled wall time), the scheduling its
/// real-time threads got and /proc/stat when the pacing started. Empty in virtual mode.
struct ScheduleRecord {
  struct Link {
    std::string name;                          ///< the link's name, or the CAN interface
    const QuantileSketch* error_us = nullptr;  ///< of each byte (serial) or frame (CAN)
    std::uint64_t bytes_dropped_unread = 0;    ///< serial: dropped, nobody read the port
  };
  std::vector<Link> serial;  ///< every serial link, in the devices' order
  std::optional<Link> can;   ///< the CAN bus, when the scenario has one
  std::vector<std::pair<std::string, link::ThreadSchedule>> threads;
  std::optional<CpuTicks> cpu_at_start;
};

/// Real time: `{"threads": [RealtimeThreadsJson], "links": [{link, bytes, bytes_dropped_unread,
/// p50_us, p99_us, max_us}]}`, the scheduling each thread really got and the schedule error per
/// link; nothing in virtual mode.
void WriteScheduleErrors(const ScheduleRecord& record, const std::string& path);
/// `[{thread, tid, policy, priority, timer_slack_ns, cpu_user_s, cpu_system_s, wall_s, cpu_pct}]`:
/// each real-time thread's scheduling as the kernel reported it and the CPU it used while the run
/// paced (getrusage RUSAGE_THREAD; cpu_pct = 100 × CPU / wall). Also report.json's
/// `realtime_threads`.
nlohmann::json RealtimeThreadsJson(
    const std::vector<std::pair<std::string, link::ThreadSchedule>>& threads);

}  // namespace hil::harness

#pragma once
/// @file
/// Adapters that turn the estimator's output lines into EstimateRecords, one per output format
/// (EstimatorSpec::output):
///  - json_stdout: navd's JSON lines ({"tov_unix_ns" (integer; else "tov_utc_s" in seconds, read to
///    the microsecond), "lat_deg", "lon_deg", "height_m", "vel_enu_mps", "yaw_deg",
///    "pos_std_enu_m"});
///  - gpsd_json: gpsd TPV objects ({"class":"TPV","time":ISO,"lat","lon","altHAE"|"alt",
///    "track","speed","climb","epx","epy","epv"}), e.g. from `gpspipe -w`; other classes skipped;
///  - nmea_stdout / nmea_pty: NMEA 0183 GGA (position, time of day) and RMC (speed, course); the
///    date comes from the scenario start (the solution closest to it), as GGA carries none;
///  - n2k_candump: NMEA 2000 PGN 129029 fast packets as `candump -L`/`-l` lines on stdout (e.g.
///    `navd … & exec candump -L vcan0`); date, time, latitude, longitude, altitude.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "hil/firmware_emu/unix_time.h"
#include "hil/harness/core/estimate_record.h"
#include "hil/harness/core/json_solution_line.h"
#include "hil/harness/scenario/estimator_kinds.h"

namespace hil::harness {

class EstimateReader {
 public:
  virtual ~EstimateReader() = default;
  /// One output line and its CLOCK_MONOTONIC arrival; a record when the line is a solution.
  virtual std::optional<EstimateRecord> Line(const std::string& text, WallTime wall) = 0;
  /// True for the JSON formats: Line() parses the text, and JsonLine() takes it parsed.
  virtual bool reads_json() const { return false; }
  /// Line() for a line already parsed (the parse result, possibly discarded).
  virtual std::optional<EstimateRecord> JsonLine(const nlohmann::json& /*line*/,
                                                 WallTime /*wall*/) {
    return std::nullopt;
  }
  /// True when a line's JsonSolutionScanner scan holds all Line() reads (json_stdout): then
  /// ScannedLine() takes the scan and gives what JsonLine() gives for the parsed line.
  virtual bool reads_scanned_lines() const { return false; }
  virtual std::optional<EstimateRecord> ScannedLine(const JsonSolutionLine& /*line*/,
                                                    WallTime /*wall*/) {
    return std::nullopt;
  }
  /// False when the solutions come from elsewhere (n2k_socketcan: the bus) and every line is a
  /// diagnostic, so a line that is no solution is not worth a warning.
  virtual bool SolutionsInLines() const { return true; }
  /// Why Line() gives no record for `text`, in a few words naming the field (for the message on
  /// the first line that was not a solution).
  virtual std::string WhyNotASolution(const std::string& text) const;
  /// True for a line that is no solution but a valid record of the format's stream (NMEA: a
  /// sentence with a good checksum other than a GGA with a fix, e.g. RMC, GSA, GSV, VTG, or a GGA
  /// without a fix): counted in the report, never warned about.
  virtual bool OtherRecordOfTheStream(const std::string& /*text*/) const { return false; }
};

/// The run folder's file of the estimator's raw output: estimate.nmea for the NMEA outputs
/// (nmea_stdout, nmea_pty), else estimate.jsonl.
const char* RawEstimateFileName(EstimatorOutput output);

/// The reader for an output format (parsed from the scenario's estimator.output).
std::unique_ptr<EstimateReader> MakeEstimateReader(EstimatorOutput output, UnixTime start_utc);

}  // namespace hil::harness

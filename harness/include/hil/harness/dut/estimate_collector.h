#pragma once
/// @file
/// Collects the estimator's output during a run, from its stdout or from the pty it writes NMEA
/// into (RUN_DIR/ttyNAV), keeps every raw line (estimate.jsonl / estimate.nmea) and the time of
/// the last output, and parses solutions with the scenario's EstimateReader.

#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/unix_time.h"
#include "hil/harness/core/run_diagnostics.h"
#include "hil/harness/dut/estimate_reader.h"
#include "hil/harness/dut/estimator_process.h"
#include "hil/harness/dut/n2k_bus_reader.h"

namespace hil::harness {

class EstimateCollector {
 public:
  /// `nav_pty` (may be null): the pty the estimator writes its solutions into. A failed write of
  /// `raw_path` is noted in `diagnostics` (may be null: nowhere).
  EstimateCollector(std::unique_ptr<EstimateReader> reader, EstimatorProcess* process,
                    link::PtyPort* nav_pty, const std::string& raw_path,
                    RunDiagnostics* diagnostics);

  /// Output n2k_socketcan: `poll_bus` polls the CAN bus and returns the frames others put on it
  /// since its last call; Poll() decodes them (N2kBusReader) into records.
  void AttachBus(std::function<std::vector<CanFrame>()> poll_bus, UnixTime start_utc);
  /// Takes what arrived since the last call.
  void Poll();
  /// Output n2k_socketcan: frames seen per PGN (empty otherwise).
  std::map<std::uint32_t, std::uint64_t> bus_frames_per_pgn() const;
  /// When the last output line came (the clock's epoch: none yet).
  WallTime last_output_wall() const;
  /// The solutions parsed since the last call, moved into `out` (cleared first): the collector
  /// keeps none for long (the run scores them as they come: run/run_scoring.h).
  void TakeRecords(std::vector<EstimateRecord>& out) {
    out.clear();
    out.swap(records_);
  }
  /// Solutions parsed so far (taken or not), and the latest one's time of validity.
  std::size_t solutions() const { return solutions_; }
  std::optional<Time> last_validity() const { return last_validity_; }
  std::size_t lines() const { return lines_; }
  std::size_t unparsed_lines() const { return unparsed_; }
  /// Lines that were valid records of the output's stream but no solution (NMEA: RMC, GSA, GSV,
  /// a GGA without a fix...; EstimateReader::OtherRecordOfTheStream).
  std::size_t other_records() const { return other_records_; }
  /// The first line that was not a solution: its number in the raw output file (1-based; 0 when
  /// every line was one) and why (EstimateReader::WhyNotASolution).
  std::size_t first_unparsed_line() const { return first_unparsed_line_; }
  const std::string& first_unparsed_reason() const { return first_unparsed_reason_; }
  /// Called with every raw line as it arrives (e.g. to read navd's health object).
  void set_line_observer(std::function<void(const std::string&)> f) { observer_ = std::move(f); }
  /// For a JSON output format, the observer of each line parsed (parsed once for both the reader
  /// and the observer); then set_line_observer's observer is not called for those lines.
  struct JsonObserver {
    std::function<void(const nlohmann::json&)> parsed;
    /// The lines the reader thread scanned instead (JsonSolutionScanner; json_stdout).
    std::function<void(const JsonSolutionLine&)> scanned;
  };
  void set_json_observer(JsonObserver f);
  /// The raw file keeps at most `bytes` (lines past it are counted, not written).
  void set_keep_limit(std::uint64_t bytes) { keep_limit_ = bytes; }
  /// Bytes of output so far (stdout, or the pty of output nmea_pty), kept or not.
  std::uint64_t output_bytes() const;
  /// Lines not written to the raw file: past the keep limit, or dropped before they were taken.
  std::uint64_t lines_not_kept() const { return not_kept_; }
  std::uint64_t bytes_kept() const { return kept_bytes_; }

 private:
  /// Poll's work, without the flush of the raw lines.
  void Take();
  /// `parsed`: the line already parsed as JSON (EstimatorProcess's reader thread), or null.
  void Consume(const std::string& line, WallTime wall, const nlohmann::json* parsed = nullptr);
  /// Consume() for a line the reader thread scanned.
  void ConsumeScanned(const std::string& line, WallTime wall, const JsonSolutionLine& scan);
  /// Lines counted and kept in the raw file.
  void Keep(const std::string& line);
  /// Writes one line to the raw file while the kept output is within its bound (else counts it).
  void Store(const std::string& line);
  /// Counts `line` (the last kept) as not a solution.
  void NotASolution(const std::string& line);
  std::unique_ptr<EstimateReader> reader_;
  EstimatorProcess* process_;
  link::PtyPort* nav_pty_;
  std::ofstream raw_;
  bool raw_unflushed_ = false;  // lines written to raw_ since its last flush
  std::string pty_partial_;
  WallTime pty_last_{};
  void AddRecord(const EstimateRecord& r);
  std::vector<EstimateRecord> records_;  // not yet taken
  std::size_t solutions_ = 0;
  std::optional<Time> last_validity_;
  std::size_t lines_ = 0, unparsed_ = 0, first_unparsed_line_ = 0, other_records_ = 0;
  std::size_t raw_lines_ = 0;  // lines of the raw file (with the pty case's "# stdout:" lines)
  std::string first_unparsed_reason_;
  std::uint64_t keep_limit_ = UINT64_MAX, kept_bytes_ = 0, not_kept_ = 0, pty_bytes_ = 0;
  std::string raw_path_;
  RunDiagnostics* diagnostics_;
  std::function<void(const std::string&)> observer_;
  JsonObserver json_observer_;
  std::function<std::vector<CanFrame>()> poll_bus_;
  std::unique_ptr<N2kBusReader> bus_reader_;
  WallTime bus_last_{};
};

}  // namespace hil::harness

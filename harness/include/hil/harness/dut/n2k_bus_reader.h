#pragma once
/// @file
/// The estimator's NMEA 2000 output as EstimateRecords, frame by frame (from the live bus,
/// output `n2k_socketcan`, or from candump lines, output `n2k_candump`). A record per PGN 129029
/// GNSS Position Data (fast packet; date, time of validity, latitude, longitude, altitude), with
/// the velocity of the 129026 COG & SOG Rapid Update and the heading of the 127250 Vessel Heading
/// that carry the same SID (navd sends them together). 129025 Position Rapid Update carries no time
/// of validity, and 127257 Attitude no field the evaluator scores: both are counted, not evaluated.
/// Layouts: canboat's database (../shared/reference/can_and_transports.md); all-ones = no data.

#include <cstdint>
#include <map>
#include <optional>
#include <string_view>

#include "hil/firmware_emu/unix_time.h"
#include "hil/harness/core/estimate_record.h"
#include "hil/harness/dut/n2k_fast_packet.h"

namespace hil::harness {

class N2kBusReader {
 public:
  /// `start_utc`: UTC of emulated t = 0 (record times are relative to it).
  explicit N2kBusReader(UnixTime start_utc) : start_(start_utc) {}
  /// One frame with a 29-bit identifier; a record when it completes a 129029.
  std::optional<EstimateRecord> Frame(std::uint32_t id29, std::string_view data, WallTime wall);
  /// Frames seen per PGN.
  const std::map<std::uint32_t, std::uint64_t>& frames_per_pgn() const { return per_pgn_; }
  const N2kFastPacketStats& fast_packet_stats() const { return fast_.stats(); }

 private:
  struct Tagged {
    int sid = -1;
    double a = 0, b = 0;
  };
  UnixTime start_;
  N2kFastPacketAssembler fast_;
  std::map<std::uint32_t, std::uint64_t> per_pgn_;
  Tagged cog_sog_, heading_;
};

}  // namespace hil::harness

#pragma once
/// @file
/// RTKLIB's TIMETAG files (`FILE.tag` beside a stream logged with the `::T` option; layout from
/// RTKLIB's src/stream.c, read there, nothing copied): a 64-byte header whose text starts
/// "TIMETAG RTKLIB" and whose last 4 bytes are the logger's tick at opening (ms, u32), then the
/// opening time in GPST (u32 seconds since 1970 and a double fraction), then one record per write
/// to the stream: the tick since opening (ms, u32) and the stream file's size after that write
/// (u32, or u64 with the logger's `::P=8` option; the file does not say which: an option here).
/// All little-endian.

#include <cstdint>
#include <string>
#include <vector>

namespace hil::harness {

struct RtklibTimeTagRecord {
  std::uint32_t tick_ms = 0;   ///< ms after the opening time
  std::uint64_t file_pos = 0;  ///< bytes of the stream written so far
};

struct RtklibTimeTag {
  std::string header;  ///< the header's text
  std::uint32_t open_tick_ms = 0;
  double open_gpst_s = 0;  ///< opening time, GPST seconds since 1970-01-01
  std::vector<RtklibTimeTagRecord> records;
};

/// @param fpos_bytes 4 (RTKLIB's default) or 8.
/// @throws ImportInputError naming the file and the record for a short or inconsistent file
/// (header text, a partial record, ticks or positions going backwards).
RtklibTimeTag ReadRtklibTimeTag(const std::string& path, int fpos_bytes = 4);

/// The GPST time (seconds since 1970) at which the byte ending at `end_pos` was written: the
/// first record whose position reaches it. @throws std::out_of_range past the last record.
double RtklibTimeTagTimeOf(const RtklibTimeTag& tag, std::uint64_t end_pos);

}  // namespace hil::harness

#pragma once
/// @file
/// The can-utils text formats: the compact frame string of `cansend`/`candump` (lib.c
/// sprint_canframe / parse_canframe) and the log line of `candump -l`, which `canplayer` replays:
///
///     (1700000000.000000) vcan0 09F80180#8868111FBFA49103
///     (SSSSSSSSSS.UUUUUU) IFACE FRAME
///
/// Seconds are zero-padded to 10 digits and microseconds to 6; the interface name may be padded on
/// the left to a common width; hexadecimal digits are upper case. Frame strings:
///  - classic: `123#DEADBEEF` (3 hex digits = 11-bit id), `12345678#01` (8 digits = 29-bit id);
///  - remote request: `123#R`, or `123#R5` with a requested length 1–8;
///  - error frame: 8 digits with CAN_ERR_FLAG 0x20000000 set in the id, e.g.
///  `20000004#0001000000000000`;
///  - CAN FD: `123##1AABB` (after `##` one hex digit of flags: BRS = 1, ESI = 2).
/// The reader is tolerant as canplayer is: lines that do not start with '(' are ignored (e.g.
/// candump's `DROPCOUNT:` lines), data bytes may be separated by '.', lower-case hex is accepted,
/// a fraction of other than 6 digits is read as a decimal fraction (candump -N writes 9), a
/// trailing ` T`/` R` direction flag (candump -x) is accepted, and `_<dlc>` length codes are
/// skipped.

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/link/can_wire_frame.h"
#include "hil/firmware_emu/unix_time.h"

namespace hil::link {

/// The CAN_ERR_FLAG bit of a 32-bit can-utils identifier.
inline constexpr std::uint32_t kCanErrFlag = 0x20000000U;

/// One log line: when, where and what.
struct CandumpRecord {
  UnixTime t{};  ///< when (the log keeps microseconds)
  std::string iface;
  CanWireFrame frame;
  char direction = 0;  ///< 'T' or 'R' when the line carried candump -x's flag, else 0
  bool operator==(const CandumpRecord&) const = default;
};

/// The compact frame string, as candump prints it (no '.' separators).
std::string FormatCanFrameText(const CanWireFrame& f);
/// Parses a frame string; nothing if it is not a classic, RTR, error or FD frame string.
std::optional<CanWireFrame> ParseCanFrameText(std::string_view s);

/// One log line without the newline. `iface_width` right-aligns the interface name as candump does
/// when it dumps several interfaces (0: no padding). The time is truncated to the microsecond.
std::string FormatCandumpLine(const CandumpRecord& r, int iface_width = 0);
/// Parses one log line; nothing for a line canplayer would skip or cannot read.
std::optional<CandumpRecord> ParseCandumpLine(std::string_view line);

/// Writes a `candump -l` compatible log, one line per frame, flushed per line so a crashed run
/// keeps everything written before.
class CandumpLogWriter {
 public:
  /// @throws std::runtime_error naming the path when it cannot be created.
  explicit CandumpLogWriter(const std::string& path);
  void Write(const CandumpRecord& r);
  std::uint64_t lines() const { return lines_; }

 private:
  std::ofstream out_;
  std::uint64_t lines_ = 0;
};

/// What a log held.
struct CandumpLog {
  std::vector<CandumpRecord> records;
  std::size_t skipped_lines = 0;     ///< lines not starting with '(' (comments, DROPCOUNT, blank)
  std::size_t unreadable_lines = 0;  ///< lines starting with '(' that did not parse
};

/// Reads a whole log. @throws std::runtime_error naming the path when it cannot be opened.
CandumpLog ReadCandumpLog(const std::string& path);

}  // namespace hil::link

#pragma once
/// @file
/// The capture format of a run: every byte and frame of one link, both directions, with emulated
/// and wall-clock times (documented in vectors/captures/README.md). One text file per link,
/// `RUN_DIR/captures/<link>.cap`:
///
///     # hil capture v2
///     # link ttyGPS serial 9600
///     # columns: dir t_emu_ns byte_period_ns t_wall_ns name data [wall_offsets_ns]
///     tx 100000000 1042 5193820011 NMEA-GGA 2447504747412c... 0,1061,2075,...
///
/// dir: tx (device → host bytes), rx (host → device bytes), drop (a message the UART dropped
/// whole, or in a real-time run bytes the UART sent that nobody could take: no process had the pty
/// open or its input queue was full; in any run, bytes still queued when it ended, never written
/// because the reader went away or the run stopped early), ftx (CAN frame the harness put on the
/// bus), frx (CAN frame read from the bus). t_emu_ns: emulated time of the first byte's start bit
/// (or of the frame). byte_period_ns: time between byte starts (0 for rx, frames and whole dropped
/// messages); byte k is at t_emu_ns + k·byte_period_ns. t_wall_ns: CLOCK_MONOTONIC when the first
/// byte was written (or the frame sent, or rx bytes read) in a real-time run; 0 in virtual mode
/// (nothing is paced there, and a scenario and seed then give a byte-identical capture) and for
/// bytes never written. data: lower-case hex bytes, or for frames the can-utils frame string
/// (`09F80180#8868111FBFA49103`). wall_offsets_ns (real-time runs): comma-separated wall time of
/// each byte minus t_wall_ns. Lines starting with '#' are comments; v1 files (no offsets) read the
/// same.

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/link/can_wire_frame.h"
#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/unix_time.h"
#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/core/run_diagnostics.h"

namespace hil::harness {

enum class CaptureDir { kTx, kRx, kDrop, kFrameTx, kFrameRx };

/// One line of a capture.
struct CaptureRecord {
  CaptureDir dir = CaptureDir::kTx;
  std::int64_t t_emu_ns = 0;
  std::int64_t byte_period_ns = 0;
  WallTime t_wall{};  ///< the column t_wall_ns; its epoch (0) when none
  std::string name = "-";
  std::string bytes;                          ///< tx, rx, drop: the raw bytes
  link::CanWireFrame frame;                   ///< ftx, frx
  std::vector<std::int64_t> wall_offsets_ns;  ///< per byte, when known

  bool is_frame() const { return dir == CaptureDir::kFrameTx || dir == CaptureDir::kFrameRx; }
  /// Emulated start time of byte k.
  Time t_byte(std::size_t k) const {
    return TimeFromNs(t_emu_ns + byte_period_ns * static_cast<std::int64_t>(k));
  }
  bool operator==(const CaptureRecord&) const = default;
};

/// What the header says about the link.
struct CaptureHeader {
  int version = 2;
  std::string link;                   ///< link name, e.g. ttyGPS or can0
  std::string kind;                   ///< "serial" or "can"
  int baud = 0;                       ///< serial: line rate
  std::string iface;                  ///< can: the interface the frames went to
  std::optional<UnixTime> start_utc;  ///< UTC of emulated t = 0, when known
};

struct Capture {
  CaptureHeader header;
  std::vector<CaptureRecord> records;
  std::size_t unreadable_lines = 0;
};

std::string_view CaptureDirName(CaptureDir d);
/// One capture line without the newline.
std::string FormatCaptureLine(const CaptureRecord& r);
/// Parses a record line; nothing for comments and lines that do not parse.
std::optional<CaptureRecord> ParseCaptureLine(std::string_view line);

/// Writes one link's capture, line by line (buffered, flushed every kBufferBytes and at the end, so
/// a crashed run keeps what it had). The file is opened close-on-exec (the estimator does not
/// inherit it). A write that fails part-way (disk full, EIO, a file size limit) leaves the file
/// ending on a record boundary followed, when it fits, by a comment line `# cut: ...` naming the
/// reason; the records after it are not written and the failure is noted in the run's
/// diagnostics (run_diagnostics.h) when the writer was given them (ReportFailuresTo).
class CaptureWriter {
 public:
  /// @throws std::runtime_error naming the path.
  CaptureWriter(const std::string& path, const CaptureHeader& header);
  /// Flushes what is buffered.
  ~CaptureWriter();
  CaptureWriter(const CaptureWriter&) = delete;
  CaptureWriter& operator=(const CaptureWriter&) = delete;
  /// Writes one record (buffered: it reaches the file with the next few kB or at Flush()); a
  /// failed write (disk full, file size limit) is noted (ReportFailuresTo) when the buffer goes
  /// out.
  void Write(const CaptureRecord& r);
  /// Writes out what is buffered.
  void Flush();
  /// Where a failed write is noted from now on (the run's diagnostics; null: nowhere, the file's
  /// `# cut:` line only). A failure before the call is noted at once.
  void ReportFailuresTo(RunDiagnostics* diagnostics);

  static constexpr std::size_t kBufferBytes = 64 * 1024;

 private:
  /// Cuts the file back to its last whole record and marks it after a write that failed with
  /// `err` having written `written` bytes of the buffer.
  void Cut(std::size_t written, int err);

  int fd_ = -1;
  std::string path_;
  std::string buf_;        ///< whole records not written yet
  std::int64_t size_ = 0;  ///< bytes in the file, all of them whole lines
  bool failed_ = false;
  RunDiagnostics* diagnostics_ = nullptr;
};

/// Reads one header comment line (`# hil capture v2`, `# link ttyGPS serial 9600`,
/// `# start_unix_ns …`, or v1's `# hil capture v1: link NAME, baud N`) into `h`; other lines leave
/// it as it was. True when the line was a header line.
bool ParseCaptureHeaderLine(std::string_view line, CaptureHeader& h);

/// Reads a capture (v1 or v2). @throws std::runtime_error naming the path when unreadable.
Capture ReadCapture(const std::string& path);

/// Lower-case hex of raw bytes, and back (nothing on odd length or a non-hex digit).
std::string ToHex(std::string_view bytes);
std::optional<std::string> FromHex(std::string_view hex);

}  // namespace hil::harness

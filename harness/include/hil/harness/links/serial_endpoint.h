#pragma once
/// @file
/// One serial port of an emulated device as the run sees it: the device's UART transmit queue, the
/// port the host opens (a pty behind a symlink in the run folder, or a real tty device), and the
/// capture of every byte both ways (capture_format.h).
/// Virtual mode writes bytes at once; real-time mode writes each byte at its UART wall time and
/// records its schedule error and its wall time in the capture.

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/link/serial_port.h"
#include "hil/firmware_emu/link/uart_tx_queue.h"
#include "hil/harness/core/quantile_sketch.h"
#include "hil/harness/links/capture_format.h"

namespace hil::harness {

class SerialEndpoint {
 public:
  /// @param link_name the scenario's link: a plain name (a pty at `link_path`) or an absolute /dev
  ///        path (that real serial device is opened and `link_path` is ignored)
  /// @param link_path symlink for the host side, e.g. RUN_DIR/ttyGPS
  /// @param capture_path capture file for this link (see CaptureFileName)
  /// @throws std::runtime_error when the port or the capture cannot be opened.
  SerialEndpoint(std::string link_name, const std::string& link_path, int baud,
                 std::size_t tx_buffer_bytes, const std::string& capture_path);
  /// Writes the bytes still queued (never written to the host: it closed the link or the run
  /// stopped early) into the capture as `drop` records with t_wall_ns = 0.
  ~SerialEndpoint();
  SerialEndpoint(const SerialEndpoint&) = delete;
  SerialEndpoint& operator=(const SerialEndpoint&) = delete;

  /// Queues one message in the UART (or records its drop). Its bytes wait in this endpoint until
  /// written by WriteAll() (virtual mode) or WriteNextByte() (real time). Returns false when the
  /// transmit buffer had no room (the message was dropped). A message timed already
  /// (SerialMessage::byte_period) bypasses the UART and keeps its times. A reply
  /// (SerialMessage::reply) goes ahead of the queued messages not yet begun at its time and not
  /// yet written to the host (UartTxQueue::SubmitAhead); they move behind it.
  bool Queue(const SerialMessage& msg);
  /// Emulated time at which the last byte queued so far leaves the UART (its stop bit ends).
  Time last_queued_end() const { return last_queued_end_; }
  /// Emulated time of the next byte waiting to be written, if any.
  std::optional<Time> next_byte_time() const;
  /// Writes the next waiting byte at its UART wall time and records the schedule error. A byte
  /// the host cannot take at that instant (nobody has the pty open, or its input queue is full) is
  /// dropped at the UART and captured as a drop, as a real UART loses what nobody reads; this
  /// never waits beyond the byte's time.
  void WriteNextByte(const link::RealtimePacer& pacer);
  /// Waits until the host's input queue takes more: calls `write_more` (which writes what the
  /// port takes now and returns the bytes still to write) until it returns 0. False: the wait was
  /// given up (the run stops).
  using RoomWait = std::function<bool(const std::function<std::size_t()>& write_more)>;
  /// Writes every waiting byte at once, in one write (virtual mode). The order in which the host
  /// sees several links is kept by VirtualGate / VirtualWriteQueue, before this is called.
  void WriteAll() { WriteChunks(pending_.size()); }
  /// Writes the first `chunks` waiting chunks in one write (virtual mode). With `wait_for_room`
  /// (a host that reads this link) nothing is dropped: while the port is full the caller waits;
  /// if it gives up, the bytes not written stay queued and this returns false. Without, a port
  /// nobody reads drops what it cannot take (PtyPort::Write). The capture records what was
  /// written as `tx` and what was dropped as `drop` (counted in bytes_dropped_unread()).
  bool WriteChunks(std::size_t chunks, const RoomWait& wait_for_room = {});
  /// Virtual mode with the programs on hil's clock (engine/clocked_pacer.h): the emulated time the
  /// first waiting chunk's last byte has left the UART at, if any.
  std::optional<Time> next_chunk_end() const;
  /// The waiting chunks, from the first, whose last byte has left the UART by `t`.
  std::size_t ChunksEndedBy(Time t) const;
  /// Writes the first `chunks` waiting chunks in one write without waiting: what the host's input
  /// queue cannot take now is dropped, as a UART's bytes that nobody reads (captured as `drop`,
  /// counted in bytes_dropped_attached()). The host is idle when this is called, so what it takes
  /// depends only on what it read before. Returns the bytes written.
  std::size_t WriteChunksOrDrop(std::size_t chunks);
  /// Bytes waiting to be written.
  std::size_t queued_bytes() const;
  /// Lockstep lookahead (engine/lookahead_writer.h): the waiting chunks, the emulated time the
  /// `i`-th one's last byte leaves the UART, and its bytes still to write.
  std::size_t queued_chunks() const { return pending_.size(); }
  Time chunk_end(std::size_t i) const { return pending_[i].first.t_end(); }
  std::size_t chunk_bytes(std::size_t i) const {
    return pending_[i].first.bytes.size() - (i == 0 ? pending_offset_ : 0);
  }
  /// Writes out the capture's buffer (a failed write is noted, ReportWriteFailuresTo).
  void FlushCapture() { capture_.Flush(); }
  /// Where the capture notes a failed write (CaptureWriter::ReportFailuresTo).
  void ReportWriteFailuresTo(RunDiagnostics* diagnostics) {
    capture_.ReportFailuresTo(diagnostics);
  }
  /// poll() shows host bytes on this descriptor (-1: none to poll, call PollHost anyway).
  int host_input_fd() const { return port_->host_input_fd(); }
  /// Reads host bytes (non-blocking), captures them with emulated time `t_now`, returns them.
  /// With `virtual_time` the capture gives no wall time (0, as for virtual mode's tx bytes).
  std::string PollHost(Time t_now, bool virtual_time = false);
  void set_baud(int baud) { uart_.set_baud(baud); }
  /// Lockstep (a closed loop in real time or scaled, engine/lockstep_pacer.h): the capture's
  /// records carry the wall-clock time of their write or read, which virtual mode leaves 0.
  void set_wall_stamps(bool on) { wall_stamps_ = on; }
  std::size_t PendingToHost() const { return port_->PendingToHost(); }
  /// What the host side holds now (SerialPort::HeldForHost: exact when nothing written is still
  /// on its way to the host side).
  std::size_t HeldForHost() const { return port_->HeldForHost(); }
  /// The host has the port open (a pty: it opened the link and has not closed it since; a real
  /// device cannot tell and says true).
  bool HostAttached() { return port_->HostAttached(); }
  const link::UartTxQueue& uart() const { return uart_; }
  const std::string& link_name() const { return link_name_; }
  const std::string& link_path() const { return port_->path(); }
  /// Bytes dropped because nobody had the port open or its input queue was full (real time), or
  /// because a port nobody reads stalled or the port failed (virtual mode).
  std::uint64_t bytes_dropped_unread() const { return bytes_dropped_unread_; }
  /// Real time: of these, the bytes dropped while the host had the port open (its input queue was
  /// full: it did not read them in time).
  std::uint64_t bytes_dropped_attached() const { return bytes_dropped_attached_; }
  /// Bytes the capture records as written to the host.
  std::uint64_t bytes_sent() const { return bytes_sent_; }
  /// Schedule errors (µs) of bytes written in real time: wall time written − scheduled wall time.
  /// A sketch, not every byte's error (8 B a byte grew without bound: issue 40): its percentiles
  /// are exact up to QuantileSketch::kExactLimit bytes and within its relative accuracy beyond.
  const QuantileSketch& schedule_error_us() const { return schedule_error_us_; }

 private:
  /// Real time: adds one byte to the capture line being built, tx when it `left`, else drop.
  void RecordRealtimeByte(bool left, Time t, WallTime wall, Duration byte_period,
                          const std::string& name, char byte);
  /// Real time: writes the capture lines being built.
  void FinishRealtimeRecords();
  /// Virtual mode: takes `bytes` waiting bytes off the queue into the capture as `dir` records
  /// (one per chunk or part of a chunk), `wall` their write time for tx.
  void Consume(std::size_t bytes, CaptureDir dir, WallTime wall);
  /// The front chunk has left (written or dropped): it is taken off the queue.
  void PopFront();
  /// Records a message the transmit buffer had no room for as a drop, once the chunks queued
  /// before it have been captured (WriteDueOverflows).
  void RecordOverflow(const SerialMessage& msg);
  /// Captures the overflow records whose preceding chunks have all left the queue.
  void WriteDueOverflows();

  std::string link_name_;
  std::unique_ptr<link::SerialPort> port_;
  link::UartTxQueue uart_;
  CaptureWriter capture_;
  std::deque<std::pair<link::TimedChunk, std::string>> pending_;  // chunk, message name
  Time last_queued_end_{};
  Time written_end_{};              // end of the last chunk taken off the queue
  std::size_t pending_offset_ = 0;  // bytes of pending_.front() already written
  CaptureRecord current_;           // real time: capture line of the bytes of a chunk that left
  CaptureRecord current_drop_;      // real time: capture line of its bytes dropped unread
  std::uint64_t bytes_dropped_unread_ = 0;
  std::uint64_t bytes_dropped_attached_ = 0;
  std::uint64_t bytes_sent_ = 0;
  QuantileSketch schedule_error_us_;
  std::string write_buffer_;  // virtual mode: the waiting chunks joined for one write
  bool wall_stamps_ = false;
  std::uint64_t chunks_queued_ = 0;  // chunks ever put on pending_
  std::uint64_t chunks_done_ = 0;    // chunks ever taken off it (written or dropped)
  /// overflow records waiting for the chunks queued before them: (chunks_queued_ then, record)
  std::deque<std::pair<std::uint64_t, CaptureRecord>> overflows_;
};

/// The capture file name of a link: `<link>.cap`, with a device path reduced to its base name
/// (`/dev/ttyUSB0` → `ttyUSB0.cap`).
std::string CaptureFileName(const std::string& link_name);

}  // namespace hil::harness

#pragma once
/// @file
/// One serial port of an emulated device as the run sees it: the device's UART transmit queue, the
/// pty the host opens (symlink in the run folder), and the capture of every byte both ways.
/// Virtual mode writes bytes at once; real-time mode writes each byte at its UART wall time and
/// records the schedule error.

#include <cstdint>
#include <deque>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/link/uart_tx_queue.h"

namespace hil::harness {

class SerialEndpoint {
 public:
  /// @param link_path symlink for the host side, e.g. RUN_DIR/ttyGPS
  /// @param capture_path capture file for this link
  SerialEndpoint(std::string link_name, const std::string& link_path, int baud, std::size_t tx_buffer_bytes,
                 const std::string& capture_path);

  /// Queues one message in the UART (or records its drop). Its bytes wait in this endpoint until
  /// written by WriteAll() (virtual mode) or WriteNextByte() (real time).
  void Queue(const SerialMessage& msg);
  /// Emulated time of the next byte waiting to be written, if any.
  std::optional<Time> next_byte_time() const;
  /// Writes the next waiting byte at its UART wall time and records the schedule error.
  void WriteNextByte(const link::RealtimePacer& pacer);
  /// Writes every waiting byte at once (virtual mode).
  void WriteAll();
  /// Reads host bytes (non-blocking), logs them, returns them.
  std::string PollHost(Time t_now);
  void set_baud(int baud) { uart_.set_baud(baud); }
  std::size_t PendingToHost() const { return pty_.PendingToHost(); }
  const link::UartTxQueue& uart() const { return uart_; }
  const std::string& link_name() const { return link_name_; }
  const std::string& link_path() const { return pty_.symlink_path(); }
  /// Schedule errors (µs) of bytes written in real time.
  const std::vector<double>& schedule_error_us() const { return schedule_error_us_; }

 private:
  std::string link_name_;
  link::PtyPort pty_;
  link::UartTxQueue uart_;
  std::ofstream capture_;
  std::deque<link::TimedChunk> pending_;
  std::size_t pending_offset_ = 0;  // bytes of pending_.front() already written
  std::vector<double> schedule_error_us_;
};

}  // namespace hil::harness

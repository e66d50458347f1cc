#pragma once
/// @file
/// `hil replay`: plays captures back at their recorded timing, byte by byte (each serial byte at
/// its own recorded UART time, unlike gpsd's gpsfake, which times whole sentences) and frame by
/// frame.
///  - a serial capture (`<link>.cap`) is played into a fresh pty whose symlink is `OUT/<link>` (or,
///    when the link was a /dev path, into that real device); its `tx` lines are the device's bytes;
///    `rx` (what the host sent) and `drop` lines are not played;
///  - a CAN capture (`<iface>.cap`, ftx lines) or a `candump -l` log (any other file whose lines
///  start
///    with '(') is played onto a SocketCAN interface.
/// Several captures of one run play together on one clock: emulated t = 0 of the captures is the
/// replay's start (a candump log's first frame is its t = 0); every CAN source goes onto one
/// interface. The captures become a ReplayDevice (replay_device.h) that the run's Engine
/// drives in real time, so a replay has the one clock of a run. What is played is captured again
/// in `OUT/captures/` in the same formats with wall-clock times, so a replay can be compared with
/// the original (identical bytes; times differ by the schedule error); what a host sends back
/// (rx lines, frames of other senders) is captured there too.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/core/quantile_sketch.h"

namespace hil::harness {

struct ReplayOptions {
  std::vector<std::string> captures;  ///< capture files and candump logs
  std::string out_dir;                ///< ptys (symlinks) and the re-capture
  double speed = 1.0;                 ///< > 1 plays faster
  double start_delay_s = 1.0;         ///< time between creating the links and emulated t = 0
  std::string can_iface;  ///< plays every CAN source onto this interface (default: as recorded)
  /// Called once the links exist, with {link name, path} each (hil prints them).
  std::function<void(const std::vector<std::pair<std::string, std::string>>&)> on_links;
};

struct ReplayResult {
  std::uint64_t bytes = 0;                 ///< serial bytes played
  std::uint64_t frames = 0;                ///< CAN frames played
  std::uint64_t frames_failed = 0;         ///< CAN frames the interface did not accept
  WallTime wall_start{};                   ///< the wall instant of emulated t = 0
  QuantileSketch byte_schedule_error_us;   ///< written − scheduled, of every byte of every link
  QuantileSketch frame_schedule_error_us;  ///< sent − scheduled, of every frame
};

/// Plays the captures; returns when the last byte and frame have left.
/// @throws std::runtime_error for an unreadable capture or a link/interface that cannot be opened.
ReplayResult ReplayCaptures(const ReplayOptions& options);

}  // namespace hil::harness

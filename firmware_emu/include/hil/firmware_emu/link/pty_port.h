#pragma once
/// @file
/// A pseudo-terminal standing in for a device's serial port. The emulator holds the master side;
/// the host (estimator, gpsd, a customer's program) opens the slave through a stable symlink such
/// as `RUN_DIR/ttyGPS`. The slave is put in raw 8N1 mode at the configured baud, but a pty does not
/// pace: callers write each byte at its UART time themselves (see RealtimePacer).
///
/// This and the other transport files are the only ones in firmware_emu that touch descriptors.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "hil/firmware_emu/link/baud_table.h"
#include "hil/firmware_emu/link/serial_port.h"

namespace hil::link {

/// Owner of one pty pair and its symlink; closes both and removes the link on destruction.
/// The emulator keeps the slave open too, so the host may close and reopen the port (gpsd does on
/// reconnect) without the master seeing a hangup; bytes written meanwhile wait for the next reader.
class PtyPort final : public SerialPort {
 public:
  /// Opens a pty pair, sets raw 8N1 at `baud` on the slave and points `symlink_path` at it
  /// (an existing link there is replaced).
  /// @throws std::runtime_error naming the path and the system error.
  PtyPort(const std::string& symlink_path, int baud);
  ~PtyPort() override;
  PtyPort(const PtyPort&) = delete;
  PtyPort& operator=(const PtyPort&) = delete;

  /// Writes all bytes to the master, waiting while the host's input queue is full. A host that
  /// reads nothing for kStallTimeoutMs marks the port stalled: from then on bytes that do not fit
  /// are dropped at once (counted in bytes_dropped_unread()) until a write goes through whole.
  /// Returns the bytes written (the rest were dropped), -1 if the pty failed (it never throws in
  /// the data path). A caller that must not lose bytes (a host that reads this link in virtual
  /// mode) writes with WriteNow() and waits for the host itself (VirtualGate::WaitForRoom).
  long Write(std::string_view bytes) override;
  /// Writes what the host's input queue has room for, without waiting (real time). Returns the
  /// bytes written (0 when the queue is full), -1 if the pty failed.
  long WriteNow(std::string_view bytes) override;
  /// True while some process other than the emulator has the slave open (inotify open/close
  /// events on it). When the last one closes it, its unread input is discarded, as a tty's is at
  /// its last close: a process opening it later reads only what was written after it opened.
  bool HostAttached() override;
  /// Bytes lost because the host did not read this port.
  std::uint64_t bytes_dropped_unread() const { return bytes_dropped_unread_; }
  static constexpr int kStallTimeoutMs = 1000;
  /// Reads whatever the host has written (non-blocking); empty if nothing.
  std::string ReadAvailable() override;
  /// Bytes written by the emulator that the host has not read yet. A pty hands written bytes to
  /// the reader's line discipline later, from a kernel work item; when the line discipline is empty
  /// this first waits for that hand-over, so 0 means exactly "the host has read every byte".
  /// Any other count is a lower bound: bytes still in the hand-over are not counted, nor those
  /// beyond the 4095 the line discipline holds (a 10 000-byte backlog reads 4095; after the host
  /// reads 3000 of it, 1095).
  std::size_t PendingToHost() const override;
  /// FIONREAD of the host side only: no poll(), so a hand-over still pending is not counted.
  std::size_t HeldForHost() const override;

  const std::string& path() const override { return symlink_path_; }
  const std::string& slave_path() const { return slave_path_; }
  const std::string& symlink_path() const { return symlink_path_; }
  int master_fd() const { return master_fd_; }
  int host_input_fd() const override { return master_fd_; }

 private:
  int master_fd_ = -1;
  int slave_fd_ = -1;  // kept open so the pty survives the host closing and reopening it
  std::string slave_path_;
  std::string symlink_path_;
  int inotify_fd_ = -1;  // open/close events of the slave; -1: unknown (then always attached)
  int host_opens_ = 0;   // processes' opens of the slave not closed yet
  bool stalled_ = false;
  std::uint64_t bytes_dropped_unread_ = 0;
};

}  // namespace hil::link

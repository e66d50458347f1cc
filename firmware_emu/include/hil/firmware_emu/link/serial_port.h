#pragma once
/// @file
/// The byte pipe between an emulated device and the host: a pty the emulator creates (PtyPort) or
/// a real serial device it opens (TtyPort). Neither paces; the link writes each byte at its time.

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace hil::link {

class SerialPort {
 public:
  virtual ~SerialPort() = default;
  /// Writes all bytes, waiting while the line's output queue is full. Returns the bytes that
  /// reached the line: all of them, or fewer when a pty nobody reads dropped the rest (PtyPort);
  /// -1 if the port failed (never throws in the data path).
  virtual long Write(std::string_view bytes) = 0;
  /// Writes what the line takes now, never waiting (real time: a UART does not wait for its
  /// listener). Returns the bytes accepted; the rest is the caller's to drop. -1 if the port
  /// failed.
  virtual long WriteNow(std::string_view bytes) = 0;
  /// Whether anyone listens: a pty knows when no process has its slave open; a real line always
  /// has its far end attached.
  virtual bool HostAttached() = 0;
  /// Bytes the host (or the real device) has sent, without blocking; empty if none.
  virtual std::string ReadAvailable() = 0;
  /// Bytes written that have not left yet (pty: not read by the host; tty: not transmitted).
  virtual std::size_t PendingToHost() const = 0;
  /// What the host side holds now without waiting for anything still on its way to it (a pty: the
  /// line discipline's count, one ioctl). Equal to PendingToHost() when every byte written has
  /// reached the host side; a lower bound otherwise. Default: PendingToHost().
  virtual std::size_t HeldForHost() const { return PendingToHost(); }
  /// A descriptor that poll() reports readable (POLLIN) when ReadAvailable() has bytes, or -1.
  virtual int host_input_fd() const { return -1; }
  /// The path the host opens (a pty's symlink) or the device path.
  virtual const std::string& path() const = 0;
};

/// Opens the port a scenario link names: an absolute path under /dev is an existing serial device
/// (TtyPort); anything else is a pty whose symlink is made at `run_dir/link` (PtyPort).
/// @throws std::runtime_error naming the path.
std::unique_ptr<SerialPort> OpenSerialLink(const std::string& run_dir, const std::string& link,
                                           int baud);

/// True when `link` names a real device (an absolute /dev path) rather than a pty in the run
/// folder.
bool IsDevicePath(const std::string& link);

}  // namespace hil::link

#pragma once
/// @file
/// navd's serial input: opens a tty or pty in raw mode, reads what is there, and reopens the
/// device when it goes away (the peer closed it, the USB adapter was unplugged). A device navd
/// only listens to is opened read-only: the harness's virtual mode then knows it never has to
/// wait for bytes from navd on that link (harness/include/hil/harness/run/virtual_gate.h).

#include <cstddef>
#include <cstdint>
#include <string>

namespace hil::navd {

class SerialDevice {
 public:
  enum Access { kReadOnly, kReadWrite };
  SerialDevice(std::string path, int baud, Access access = kReadOnly)
      : path_(std::move(path)), baud_(baud), access_(access) {}
  ~SerialDevice();
  SerialDevice(const SerialDevice&) = delete;
  SerialDevice& operator=(const SerialDevice&) = delete;

  /// Opens the device if it is closed; returns the descriptor, or −1 if it cannot be opened now.
  int EnsureOpen();
  /// Reads available bytes into `out` (appending), at most kMaxReadBytes per call so that after a
  /// stall (the host was busy, the kernel queued seconds of input on every device) the devices are
  /// served in turns and their streams stay interleaved in time: reading one device's whole
  /// backlog first would run the IMU seconds ahead of GNSS fixes still queued on the other
  /// device, which then arrive too late to fuse. Returns false when the device closed or failed,
  /// in which case it is closed and will be reopened by the next EnsureOpen().
  /// A read shorter than asked for ends the call: the device had no more bytes then (one read
  /// per call instead of a last one that finds nothing; poll() reports what comes later).
  bool Read(std::string& out);
  static constexpr std::size_t kMaxReadBytes = 512;
  /// Whether the last Read() took every byte the device had (false: it stopped at
  /// kMaxReadBytes, and more are probably waiting).
  bool drained() const { return drained_; }
  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  std::uint64_t reopen_count() const { return reopens_; }

 private:
  void Close();
  std::string path_;
  int baud_;
  Access access_;
  int fd_ = -1;
  std::uint64_t reopens_ = 0;
  bool opened_once_ = false;
  bool drained_ = true;
};

}  // namespace hil::navd

#pragma once
/// @file
/// A real serial device (`/dev/ttyUSB0`, `/dev/ttyS1`, …) standing in for a pty, so the harness can
/// drive real hardware or read a real receiver. Opened raw 8N1 at the configured baud; its UART
/// paces the bytes. A device that goes away (USB unplugged, EIO/ENXIO) is reopened on the next
/// write or read, so a reset of the peer does not end the run.

#include <string>

#include "hil/firmware_emu/link/serial_port.h"

namespace hil::link {

class TtyPort final : public SerialPort {
 public:
  /// @throws std::runtime_error naming the device and the system error.
  TtyPort(const std::string& device_path, int baud);
  ~TtyPort() override;
  TtyPort(const TtyPort&) = delete;
  TtyPort& operator=(const TtyPort&) = delete;

  long Write(std::string_view bytes) override;
  /// Writes what the output queue takes now (the UART paces it); a full queue takes nothing.
  long WriteNow(std::string_view bytes) override;
  /// A device's line always has its far end (whatever is wired to it).
  bool HostAttached() override { return true; }
  std::string ReadAvailable() override;
  std::size_t PendingToHost() const override;
  const std::string& path() const override { return path_; }
  int fd() const { return fd_; }
  int host_input_fd() const override { return fd_; }
  /// How often the device was reopened after failing.
  int reopen_count() const { return reopens_; }

 private:
  bool Open();
  bool Reopen();

  std::string path_;
  int baud_;
  int fd_ = -1;
  int reopens_ = 0;
};

/// Puts `fd` in raw 8N1 mode at `baud` (receiver on, modem lines ignored). False on failure.
bool SetRaw8N1(int fd, int baud);

}  // namespace hil::link

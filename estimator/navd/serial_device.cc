#include "serial_device.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

#include "hil/estimator/navd/serial_bauds.h"

namespace hil::navd {
SerialDevice::~SerialDevice() { Close(); }

void SerialDevice::Close() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

int SerialDevice::EnsureOpen() {
  if (fd_ >= 0) return fd_;
  const int mode = access_ == kReadWrite ? O_RDWR : O_RDONLY;
  fd_ = open(path_.c_str(), mode | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) return -1;
  termios tio{};
  if (tcgetattr(fd_, &tio) == 0) {
    cfmakeraw(&tio);
    tio.c_cflag |= CLOCAL | CREAD;
    // the configuration accepts only the rates of kSerialBauds
    if (const std::optional<speed_t> speed = SerialSpeed(baud_)) {
      cfsetispeed(&tio, *speed);
      cfsetospeed(&tio, *speed);
    }
    tcsetattr(fd_, TCSANOW, &tio);
  }
  if (opened_once_) ++reopens_;
  opened_once_ = true;
  return fd_;
}

bool SerialDevice::Read(std::string& out) {
  if (fd_ < 0) return false;
  char buf[kMaxReadBytes];
  drained_ = true;
  for (std::size_t total = 0; total < kMaxReadBytes;) {
    const std::size_t want = kMaxReadBytes - total;
    const ssize_t n = read(fd_, buf, want);
    if (n > 0) {
      out.append(buf, static_cast<std::size_t>(n));
      total += static_cast<std::size_t>(n);
      if (static_cast<std::size_t>(n) < want) return true;  // all it had
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return true;
    Close();  // EOF or EIO: the peer went away
    return false;
  }
  drained_ = false;
  return true;  // more may be waiting: poll() reports it again at once
}

}  // namespace hil::navd

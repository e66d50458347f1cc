#include "hil/firmware_emu/link/tty_port.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <sys/ioctl.h>

#include "hil/firmware_emu/link/pty_port.h"

namespace hil::link {

bool SetRaw8N1(int fd, int baud) {
  termios tio{};
  if (tcgetattr(fd, &tio) != 0) return false;
  cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD | CS8;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS);
  tio.c_cc[VMIN] = 1;  // a blocking read by the host waits for a byte, as on a real port
  tio.c_cc[VTIME] = 0;
  if (const unsigned speed = BaudToSpeed(baud); speed != 0) {
    cfsetispeed(&tio, speed);
    cfsetospeed(&tio, speed);
  }
  return tcsetattr(fd, TCSANOW, &tio) == 0;
}

bool IsDevicePath(const std::string& link) { return link.rfind("/dev/", 0) == 0; }

std::unique_ptr<SerialPort> OpenSerialLink(const std::string& run_dir, const std::string& link,
                                           int baud) {
  if (IsDevicePath(link)) return std::make_unique<TtyPort>(link, baud);
  return std::make_unique<PtyPort>(run_dir + "/" + link, baud);
}

TtyPort::TtyPort(const std::string& device_path, int baud) : path_(device_path), baud_(baud) {
  if (!Open())
    throw std::runtime_error("cannot open the serial device " + path_ + ": " +
                             std::strerror(errno));
}

TtyPort::~TtyPort() {
  if (fd_ >= 0) close(fd_);
}

bool TtyPort::Open() {
  fd_ = open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) return false;
  if (!isatty(fd_) || !SetRaw8N1(fd_, baud_)) {
    const int e = isatty(fd_) ? errno : ENOTTY;
    close(fd_);
    fd_ = -1;
    errno = e;
    return false;
  }
  return true;
}

bool TtyPort::Reopen() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  if (!Open()) return false;
  ++reopens_;
  return true;
}

long TtyPort::Write(std::string_view bytes) {
  if (fd_ < 0 && !Reopen()) return -1;
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd_, POLLOUT, 0};
      poll(&p, 1, 50);
    } else {
      // the device went away (EIO, ENXIO): try once to get it back
      if (!Reopen()) return -1;
    }
  }
  return static_cast<long>(done);
}

long TtyPort::WriteNow(std::string_view bytes) {
  if (fd_ < 0 && !Reopen()) return -1;
  for (;;) {
    const ssize_t n = write(fd_, bytes.data(), bytes.size());
    if (n >= 0) return n;
    if (errno == EINTR) continue;
    if (errno == EAGAIN) return 0;
    return Reopen() ? 0 : -1;  // the device went away: the bytes are lost, the port may be back
  }
}

std::string TtyPort::ReadAvailable() {
  std::string out;
  if (fd_ < 0 && !Reopen()) return out;
  char buf[512];
  for (;;) {
    const ssize_t n = read(fd_, buf, sizeof buf);
    if (n > 0) {
      out.append(buf, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) Reopen();
    break;
  }
  return out;
}

std::size_t TtyPort::PendingToHost() const {
  int n = 0;
  if (fd_ < 0 || ioctl(fd_, TIOCOUTQ, &n) != 0) return 0;
  return static_cast<std::size_t>(n);
}

}  // namespace hil::link

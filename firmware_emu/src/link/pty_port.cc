#include "hil/firmware_emu/link/pty_port.h"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <sys/inotify.h>
#include <sys/ioctl.h>

#include "hil/firmware_emu/link/sys_error.h"
#include "hil/firmware_emu/link/tty_port.h"

namespace hil::link {
unsigned BaudToSpeed(int baud) {
  for (const BaudSpeed& b : kBaudSpeeds) {
    if (b.baud == baud) return b.speed;
  }
  return 0;
}

PtyPort::PtyPort(const std::string& symlink_path, int baud) : symlink_path_(symlink_path) {
  master_fd_ = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (master_fd_ < 0) throw SysError("cannot open a pty for " + symlink_path);
  if (grantpt(master_fd_) != 0 || unlockpt(master_fd_) != 0) {
    close(master_fd_);
    throw SysError("cannot unlock the pty for " + symlink_path);
  }
  char name[128];
  if (ptsname_r(master_fd_, name, sizeof name) != 0) {
    close(master_fd_);
    throw SysError("cannot name the pty for " + symlink_path);
  }
  slave_path_ = name;
  slave_fd_ = open(name, O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (slave_fd_ < 0) {
    close(master_fd_);
    throw SysError("cannot open " + slave_path_);
  }
  SetRaw8N1(slave_fd_, baud);
  const int flags = fcntl(master_fd_, F_GETFL);
  fcntl(master_fd_, F_SETFL, flags | O_NONBLOCK);

  // who else opens the slave from now on (our own open above is not counted)
  inotify_fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_fd_ >= 0 && inotify_add_watch(inotify_fd_, name, IN_OPEN | IN_CLOSE) < 0) {
    close(inotify_fd_);
    inotify_fd_ = -1;
  }

  unlink(symlink_path.c_str());
  if (symlink(slave_path_.c_str(), symlink_path.c_str()) != 0) {
    if (inotify_fd_ >= 0) close(inotify_fd_);
    close(slave_fd_);
    close(master_fd_);
    throw SysError("cannot create the link " + symlink_path + " -> " + slave_path_);
  }
}

PtyPort::~PtyPort() {
  unlink(symlink_path_.c_str());
  if (inotify_fd_ >= 0) close(inotify_fd_);
  if (slave_fd_ >= 0) close(slave_fd_);
  if (master_fd_ >= 0) close(master_fd_);
}

long PtyPort::WriteNow(std::string_view bytes) {
  for (;;) {
    const ssize_t n = write(master_fd_, bytes.data(), bytes.size());
    if (n >= 0) return n;
    if (errno == EINTR) continue;
    return errno == EAGAIN ? 0 : -1;
  }
}

bool PtyPort::HostAttached() {
  if (inotify_fd_ < 0) return true;  // cannot tell: as if someone listened
  alignas(inotify_event) char buf[4096];
  for (;;) {
    const ssize_t n = read(inotify_fd_, buf, sizeof buf);
    if (n <= 0) break;
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buf + at);
      if (e->mask & IN_OPEN) ++host_opens_;
      if ((e->mask & IN_CLOSE) && host_opens_ > 0 && --host_opens_ == 0)
        tcflush(slave_fd_, TCIFLUSH);  // the last listener left: what it did not read is gone
      if (e->mask & IN_Q_OVERFLOW) host_opens_ = 1;  // events lost: assume someone listens
      at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
    }
  }
  return host_opens_ > 0;
}

long PtyPort::Write(std::string_view bytes) {
  std::size_t done = 0;
  int waited_ms = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(master_fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      waited_ms = 0;
    } else if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
      // The host's input queue is full. Wait for it to read (back-pressure keeps virtual runs
      // lossless), but a host that does not read this port at all must not stall the run: like a
      // UART with no listener, the bytes are then lost, and counted.
      if (stalled_ || waited_ms >= kStallTimeoutMs) {
        stalled_ = true;
        bytes_dropped_unread_ += bytes.size() - done;
        return static_cast<long>(done);
      }
      pollfd p{master_fd_, POLLOUT, 0};
      poll(&p, 1, 50);
      waited_ms += 50;
    } else {
      return -1;
    }
  }
  stalled_ = false;
  return static_cast<long>(done);
}

std::string PtyPort::ReadAvailable() {
  std::string out;
  char buf[512];
  for (;;) {
    const ssize_t n = read(master_fd_, buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  return out;
}

std::size_t PtyPort::HeldForHost() const {
  int n = 0;
  if (ioctl(slave_fd_, FIONREAD, &n) != 0) return 0;
  return static_cast<std::size_t>(n);
}

std::size_t PtyPort::PendingToHost() const {
  int n = 0;
  if (ioctl(slave_fd_, FIONREAD, &n) != 0) return 0;
  if (n > 0)
    return static_cast<std::size_t>(n);  // unread bytes wait: the hand-over does not matter
  // poll() on the slave side runs the pending hand-over (flush_to_ldisc) when its line discipline
  // has no input, so bytes in flight show in FIONREAD now instead of looking read
  pollfd p{slave_fd_, POLLIN, 0};
  poll(&p, 1, 0);
  if (ioctl(slave_fd_, FIONREAD, &n) != 0) return 0;
  return static_cast<std::size_t>(n);
}

}  // namespace hil::link

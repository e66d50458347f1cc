// A blocking read of a descriptor with nothing to read waits in emulated time (README.md): the
// read happens when a look without blocking finds bytes (or an end, an error). A terminal in
// non-canonical mode with VMIN 0 and VTIME > 0 gives up after VTIME tenths of a second of
// emulated time, as the line discipline would. Non-blocking descriptors and descriptors with
// something to read are the real read.
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

#include "preload_state.h"

namespace {

namespace pl = hil::preload;

long Readable(void* a) {
  pollfd p{*static_cast<int*>(a), POLLIN, 0};
  return pl::Real().poll(&p, 1, 0);
}

std::uint64_t Links(void* a) { return pl::LinkBitOf(*static_cast<int*>(a)); }

}  // namespace

extern "C" ssize_t read(int fd, void* buf, size_t n) {
  if (!pl::SharedState() || n == 0) return pl::Real().read(fd, buf, n);
  pollfd p{fd, POLLIN, 0};
  if (pl::Real().poll(&p, 1, 0) != 0) return pl::Real().read(fd, buf, n);  // ready, or a file
  const int flags = fcntl(fd, F_GETFL);
  if (flags < 0 || (flags & O_NONBLOCK) != 0) return pl::Real().read(fd, buf, n);
  std::int64_t deadline = hil::harness::lockstep::kNoDeadline;
  termios tio{};
  if (tcgetattr(fd, &tio) == 0 && (tio.c_lflag & ICANON) == 0 && tio.c_cc[VMIN] == 0) {
    if (tio.c_cc[VTIME] == 0) return pl::Real().read(fd, buf, n);
    deadline = pl::EmulatedNowNs() + static_cast<std::int64_t>(tio.c_cc[VTIME]) * 100'000'000;
  }
  const int saved_errno = errno;
  int fd_arg = fd;
  const long r = pl::Wait(Readable, &fd_arg, deadline, Links);
  if (r == pl::kUnmanaged) return pl::Real().read(fd, buf, n);
  if (r == pl::kInterrupted) {
    errno = EINTR;
    return -1;
  }
  if (r == pl::kDeadline) {
    errno = saved_errno;
    return 0;  // VTIME passed without a byte
  }
  return pl::Real().read(fd, buf, n);
}

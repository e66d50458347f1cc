// A blocking read of a descriptor with nothing to read waits in emulated time (README.md): the
// read happens when a look without blocking finds bytes (or an end, an error). A terminal in
// non-canonical mode with VMIN 0 and VTIME > 0 gives up after VTIME tenths of a second of
// emulated time, as the line discipline would. Non-blocking descriptors and descriptors with
// something to read are the real read. While hil writes ahead (lockstep_advance.h), a link's
// read takes exactly the bytes that have arrived by the emulated time (at most as many as asked):
// the pty may hold more, which the program reads when their time comes.
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdarg>

#include <sys/ioctl.h>

#include "preload_state.h"

namespace {

namespace pl = hil::preload;

long Readable(void* a) {
  pollfd p{*static_cast<int*>(a), POLLIN, 0};
  return pl::Real().poll(&p, 1, 0);
}

std::uint64_t Links(void* a) { return pl::LinkBitOf(*static_cast<int*>(a)); }

long FeedReadable(void* a) { return pl::FeedAvailable(*static_cast<int*>(a)) > 0 ? 1 : 0; }
std::uint64_t FeedLink(void* a) { return std::uint64_t{1} << *static_cast<int*>(a); }

// The emulated instant a blocking read of `fd` gives up: VTIME tenths of a second from now on a
// non-canonical terminal with VMIN 0, kNoDeadline otherwise. False: VMIN 0 and VTIME 0, a read
// that never waits.
bool ReadDeadline(int fd, std::int64_t& deadline) {
  deadline = hil::harness::lockstep::kNoDeadline;
  termios tio{};
  if (tcgetattr(fd, &tio) == 0 && (tio.c_lflag & ICANON) == 0 && tio.c_cc[VMIN] == 0) {
    if (tio.c_cc[VTIME] == 0) return false;
    deadline = pl::EmulatedNowNs() + static_cast<std::int64_t>(tio.c_cc[VTIME]) * 100'000'000;
  }
  return true;
}

enum class ByteWait { kRead, kRealRead, kReturnZero, kInterrupted };

// Waits in emulated time until `ready(arg)` (pl::Wait): kRead, the byte is there; kRealRead, no
// slot (block the real way); kReturnZero, VTIME passed without a byte (errno as it was);
// kInterrupted, a signal (errno EINTR).
ByteWait WaitForByte(long (*ready)(void*), void* arg, std::int64_t deadline,
                     std::uint64_t (*links)(void*)) {
  const int saved_errno = errno;
  const long r = pl::Wait(ready, arg, deadline, links);
  if (r == pl::kUnmanaged) return ByteWait::kRealRead;
  if (r == pl::kInterrupted) {
    errno = EINTR;
    return ByteWait::kInterrupted;
  }
  if (r == pl::kDeadline) {
    errno = saved_errno;
    return ByteWait::kReturnZero;
  }
  return ByteWait::kRead;
}

// Reads exactly `want` bytes that hil has written already (the kernel may still be handing
// some of them to the host side: they are waited for). Fewer only at an end or an error.
ssize_t ReadWritten(int fd, char* buf, size_t want) {
  size_t got = 0;
  while (got < want) {
    const ssize_t r = pl::Real().read(fd, buf + got, want - got);
    if (r > 0) {
      got += static_cast<size_t>(r);
      continue;
    }
    if (r < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd p{fd, POLLIN, 0};
      pl::Real().poll(&p, 1, -1);
      continue;
    }
    if (got == 0) return r;
    break;
  }
  return static_cast<ssize_t>(got);
}

// A read of link feed `k` while hil writes ahead: waits (a blocking descriptor) until bytes have
// arrived, then takes those.
ssize_t FeedRead(int fd, int k, void* buf, size_t n) {
  if (pl::FeedAvailable(k) == 0) {
    const int flags = fcntl(fd, F_GETFL);
    if (flags >= 0 && (flags & O_NONBLOCK) != 0) {
      errno = EAGAIN;
      return -1;
    }
    std::int64_t deadline = 0;
    if (!ReadDeadline(fd, deadline)) return 0;
    int k_arg = k;
    switch (WaitForByte(FeedReadable, &k_arg, deadline, FeedLink)) {
      case ByteWait::kRealRead:
        return pl::Real().read(fd, buf, n);
      case ByteWait::kInterrupted:
        return -1;
      case ByteWait::kReturnZero:
        return 0;
      case ByteWait::kRead:
        break;
    }
  }
  const std::uint64_t avail = pl::FeedAvailable(k);
  const size_t want = avail < n ? static_cast<size_t>(avail) : n;
  const ssize_t got = ReadWritten(fd, static_cast<char*>(buf), want);
  if (got > 0) pl::FeedConsumed(k, static_cast<std::uint64_t>(got));
  return got;
}

}  // namespace

extern "C" ssize_t read(int fd, void* buf, size_t n) {
  if (!pl::SharedState() || n == 0) return pl::Real().read(fd, buf, n);
  if (const int k = pl::FeedOf(fd); k >= 0) return FeedRead(fd, k, buf, n);
  pollfd p{fd, POLLIN, 0};
  if (pl::Real().poll(&p, 1, 0) != 0) return pl::Real().read(fd, buf, n);  // ready, or a file
  const int flags = fcntl(fd, F_GETFL);
  if (flags < 0 || (flags & O_NONBLOCK) != 0) return pl::Real().read(fd, buf, n);
  std::int64_t deadline = 0;
  if (!ReadDeadline(fd, deadline)) return pl::Real().read(fd, buf, n);
  int fd_arg = fd;
  switch (WaitForByte(Readable, &fd_arg, deadline, Links)) {
    case ByteWait::kInterrupted:
      return -1;
    case ByteWait::kReturnZero:
      return 0;  // VTIME passed without a byte
    case ByteWait::kRead:
    case ByteWait::kRealRead:
      break;
  }
  return pl::Real().read(fd, buf, n);
}

// FIONREAD (TIOCINQ) of a link while hil writes ahead: the bytes that have arrived, not what the
// pty holds.
extern "C" int ioctl(int fd, unsigned long request, ...) noexcept {
  va_list ap;
  va_start(ap, request);
  void* arg = va_arg(ap, void*);
  va_end(ap);
  if (request == FIONREAD && pl::SharedState()) {
    if (const int k = pl::FeedOf(fd); k >= 0 && arg) {
      const std::uint64_t avail = pl::FeedAvailable(k);
      *static_cast<int*>(arg) = avail > INT_MAX ? INT_MAX : static_cast<int>(avail);
      return 0;
    }
  }
  return pl::Real().ioctl(fd, request, arg);
}

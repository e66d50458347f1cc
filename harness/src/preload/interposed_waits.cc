// Waits for descriptors that expire in emulated time (README.md): poll, ppoll, select, pselect,
// epoll_wait and epoll_pwait. A zero timeout is the real call; any other looks at the
// descriptors without blocking each time hil moves time on or another thread waits, until one is
// ready or emulated time reaches the timeout. A signal ends the wait with EINTR. While hil writes
// ahead (lockstep_advance.h) a link is readable when bytes have arrived by the emulated time,
// whatever the pty holds, with a zero timeout too.
#include <poll.h>
#include <pthread.h>
#include <signal.h>

#include <cerrno>
#include <cstdint>

#include <sys/epoll.h>
#include <sys/select.h>

#include "preload_state.h"

namespace {

namespace pl = hil::preload;
using hil::harness::lockstep::kEveryGrant;
using hil::harness::lockstep::kNoDeadline;
using hil::harness::lockstep::kOtherFd;

std::int64_t DeadlineAfterMs(int timeout_ms) {
  return timeout_ms < 0 ? kNoDeadline
                        : pl::EmulatedNowNs() + static_cast<std::int64_t>(timeout_ms) * 1'000'000;
}

std::int64_t DeadlineAfter(const timespec* ts) {
  return ts ? pl::EmulatedNowNs() + pl::ToNs(*ts) : kNoDeadline;
}

// The answer of a wait to its caller: ready's count, 0 at the deadline, -1 EINTR.
int Answer(long r) {
  if (r == pl::kInterrupted) {
    errno = EINTR;
    return -1;
  }
  return static_cast<int>(r);
}

// The feeds of up to this many descriptors of one call are looked up once (one fstat each).
constexpr nfds_t kFeedCache = 16;

struct PollArgs {
  pollfd* fds;
  nfds_t n;
  int feeds[kFeedCache];  // per descriptor: its feed, or -1 (when `have_feeds`)
  bool have_feeds;
};

// The feed of the i-th descriptor: from the call's cache once hil writes ahead (it never stops:
// a descriptor's feed stays what it was for the rest of the call).
int FeedOfPolled(PollArgs* p, nfds_t i) {
  if (p->n > kFeedCache) return p->fds[i].fd < 0 ? -1 : pl::FeedOf(p->fds[i].fd);
  if (!p->have_feeds) {
    const auto* sh = pl::SharedState();
    if (!sh || sh->lookahead.load() == 0) return -1;
    for (nfds_t j = 0; j < p->n; ++j)
      p->feeds[j] = p->fds[j].fd < 0 ? -1 : pl::FeedOf(p->fds[j].fd);
    p->have_feeds = true;
  }
  return p->feeds[i];
}
// While hil writes ahead: POLLIN of the links with a feed as their arrived bytes say; returns
// the descriptors with events again.
int FeedPollEvents(PollArgs* p, int ready) {
  if (ready < 0) return ready;
  pollfd* fds = p->fds;
  int count = 0;
  for (nfds_t i = 0; i < p->n; ++i) {
    const int k = FeedOfPolled(p, i);
    if (k >= 0) {
      const short in = static_cast<short>(fds[i].events & (POLLIN | POLLRDNORM));
      fds[i].revents = static_cast<short>(fds[i].revents & ~(POLLIN | POLLRDNORM));
      if (pl::FeedAvailable(k) > 0) fds[i].revents = static_cast<short>(fds[i].revents | in);
    }
    count += fds[i].revents != 0 ? 1 : 0;
  }
  return count;
}
long PollReady(void* a) {
  auto* p = static_cast<PollArgs*>(a);
  return FeedPollEvents(p, pl::Real().poll(p->fds, p->n, 0));
}
std::uint64_t PollLinks(void* a) {
  auto* p = static_cast<PollArgs*>(a);
  std::uint64_t links = 0;
  for (nfds_t i = 0; i < p->n; ++i) {
    if (p->fds[i].fd < 0) continue;
    const int k = FeedOfPolled(p, i);
    const std::uint64_t bit = k >= 0 ? std::uint64_t{1} << k : pl::LinkBitOf(p->fds[i].fd);
    links |= bit;
    if (bit == kOtherFd && (p->fds[i].events & (POLLOUT | POLLWRNORM | POLLWRBAND)) != 0)
      links |= kEveryGrant;  // room in a pipe hil's threads read
  }
  return links;
}

struct SelectArgs {
  int nfds;
  fd_set *r, *w, *e;
  fd_set r0, w0, e0;  // the caller's sets, asked again at every look
};
// While hil writes ahead: the read set's links with a feed as their arrived bytes say; returns
// the count again.
int FeedSelectReady(SelectArgs* s, int ready) {
  if (ready < 0 || !s->r) return ready;
  for (int fd = 0; fd < s->nfds && fd < FD_SETSIZE; ++fd) {
    if (!FD_ISSET(fd, &s->r0)) continue;
    const int k = pl::FeedOf(fd);
    if (k < 0) continue;
    const bool was = FD_ISSET(fd, s->r);
    const bool now = pl::FeedAvailable(k) > 0;
    if (was && !now) {
      FD_CLR(fd, s->r);
      --ready;
    } else if (!was && now) {
      FD_SET(fd, s->r);
      ++ready;
    }
  }
  return ready;
}
long SelectReady(void* a) {
  auto* s = static_cast<SelectArgs*>(a);
  if (s->r) *s->r = s->r0;
  if (s->w) *s->w = s->w0;
  if (s->e) *s->e = s->e0;
  timeval zero{0, 0};
  return FeedSelectReady(s, pl::Real().select(s->nfds, s->r, s->w, s->e, &zero));
}
// Whether hil writes ahead (a zero timeout then looks at the feeds too).
bool Feeding() {
  const auto* sh = pl::SharedState();
  return sh && sh->lookahead.load() != 0;
}
std::uint64_t SelectLinks(void* a) {
  auto* s = static_cast<SelectArgs*>(a);
  std::uint64_t links = 0;
  for (int fd = 0; fd < s->nfds && fd < FD_SETSIZE; ++fd) {
    const bool out = s->w && FD_ISSET(fd, &s->w0);
    if (!out && !(s->r && FD_ISSET(fd, &s->r0)) && !(s->e && FD_ISSET(fd, &s->e0))) continue;
    const std::uint64_t bit = pl::LinkBitOf(fd);
    links |= bit;
    if (bit == kOtherFd && out) links |= kEveryGrant;  // room in a pipe hil's threads read
  }
  return links;
}
SelectArgs MakeSelectArgs(int nfds, fd_set* r, fd_set* w, fd_set* e) {
  SelectArgs s{nfds, r, w, e, {}, {}, {}};
  if (r) s.r0 = *r;
  if (w) s.w0 = *w;
  if (e) s.e0 = *e;
  return s;
}
void ClearSets(SelectArgs& s) {
  if (s.r) FD_ZERO(s.r);
  if (s.w) FD_ZERO(s.w);
  if (s.e) FD_ZERO(s.e);
}

struct EpollArgs {
  int epfd;
  epoll_event* events;
  int max;
};
long EpollReady(void* a) {
  auto* p = static_cast<EpollArgs*>(a);
  return pl::Real().epoll_wait(p->epfd, p->events, p->max, 0);
}

// Waits with the signal mask `mask` in force (ppoll, pselect, epoll_pwait), if given.
long WaitMasked(long (*ready)(void*), void* arg, std::int64_t deadline, const sigset_t* mask,
                std::uint64_t (*links)(void*)) {
  sigset_t old;
  if (mask) pthread_sigmask(SIG_SETMASK, mask, &old);
  const long r = pl::Wait(ready, arg, deadline, links);
  if (mask) pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return r;
}

}  // namespace

extern "C" {

int poll(pollfd* fds, nfds_t n, int timeout_ms) {
  PollArgs a{fds, n, {}, false};
  if (timeout_ms == 0 && Feeding()) return FeedPollEvents(&a, pl::Real().poll(fds, n, 0));
  if (timeout_ms == 0 || !pl::SharedState()) return pl::Real().poll(fds, n, timeout_ms);
  const long r = pl::Wait(PollReady, &a, DeadlineAfterMs(timeout_ms), PollLinks);
  if (r == pl::kUnmanaged) return pl::Real().poll(fds, n, timeout_ms);
  return Answer(r);
}

int ppoll(pollfd* fds, nfds_t n, const timespec* timeout, const sigset_t* mask) {
  const bool zero = timeout && timeout->tv_sec == 0 && timeout->tv_nsec == 0;
  PollArgs a{fds, n, {}, false};
  if (zero && Feeding()) return FeedPollEvents(&a, pl::Real().ppoll(fds, n, timeout, mask));
  if (zero || !pl::SharedState()) return pl::Real().ppoll(fds, n, timeout, mask);
  const long r = WaitMasked(PollReady, &a, DeadlineAfter(timeout), mask, PollLinks);
  if (r == pl::kUnmanaged) return pl::Real().ppoll(fds, n, timeout, mask);
  return Answer(r);
}

int select(int nfds, fd_set* r, fd_set* w, fd_set* e, timeval* timeout) {
  const bool zero = timeout && timeout->tv_sec == 0 && timeout->tv_usec == 0;
  if (zero && Feeding()) {
    SelectArgs a = MakeSelectArgs(nfds, r, w, e);
    return static_cast<int>(SelectReady(&a));
  }
  if (zero || !pl::SharedState()) return pl::Real().select(nfds, r, w, e, timeout);
  SelectArgs a = MakeSelectArgs(nfds, r, w, e);
  const std::int64_t deadline =
      timeout ? pl::EmulatedNowNs() + timeout->tv_sec * 1'000'000'000LL + timeout->tv_usec * 1000LL
              : kNoDeadline;
  const long res = pl::Wait(SelectReady, &a, deadline, SelectLinks);
  if (res == pl::kUnmanaged) return pl::Real().select(nfds, r, w, e, timeout);
  if (res == pl::kDeadline) ClearSets(a);
  if (res == pl::kDeadline && timeout) *timeout = timeval{0, 0};  // Linux: the time left
  return Answer(res);
}

int pselect(int nfds, fd_set* r, fd_set* w, fd_set* e, const timespec* timeout,
            const sigset_t* mask) {
  const bool zero = timeout && timeout->tv_sec == 0 && timeout->tv_nsec == 0;
  if (zero && Feeding()) {
    SelectArgs a = MakeSelectArgs(nfds, r, w, e);
    return static_cast<int>(SelectReady(&a));
  }
  if (zero || !pl::SharedState()) return pl::Real().pselect(nfds, r, w, e, timeout, mask);
  SelectArgs a = MakeSelectArgs(nfds, r, w, e);
  const long res = WaitMasked(SelectReady, &a, DeadlineAfter(timeout), mask, SelectLinks);
  if (res == pl::kUnmanaged) return pl::Real().pselect(nfds, r, w, e, timeout, mask);
  if (res == pl::kDeadline) ClearSets(a);
  return Answer(res);
}

int epoll_wait(int epfd, epoll_event* events, int max, int timeout_ms) {
  pl::NoteEpoll();
  if (timeout_ms == 0 || !pl::SharedState())
    return pl::Real().epoll_wait(epfd, events, max, timeout_ms);
  EpollArgs a{epfd, events, max};
  const long r = pl::Wait(EpollReady, &a, DeadlineAfterMs(timeout_ms));
  if (r == pl::kUnmanaged) return pl::Real().epoll_wait(epfd, events, max, timeout_ms);
  return Answer(r);
}

int epoll_pwait(int epfd, epoll_event* events, int max, int timeout_ms, const sigset_t* mask) {
  pl::NoteEpoll();
  if (timeout_ms == 0 || !pl::SharedState())
    return pl::Real().epoll_pwait(epfd, events, max, timeout_ms, mask);
  EpollArgs a{epfd, events, max};
  const long r = WaitMasked(EpollReady, &a, DeadlineAfterMs(timeout_ms), mask, nullptr);
  if (r == pl::kUnmanaged) return pl::Real().epoll_pwait(epfd, events, max, timeout_ms, mask);
  return Answer(r);
}

}  // extern "C"

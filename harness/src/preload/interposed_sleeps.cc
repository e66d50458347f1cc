// Sleeps that expire in emulated time (README.md): nanosleep, clock_nanosleep on an emulated
// clock (relative or TIMER_ABSTIME), usleep and sleep. A signal ends them with EINTR and the
// emulated time left in `rem`.
#include <time.h>
#include <unistd.h>

#include <cerrno>

#include "preload_state.h"

namespace {

using hil::preload::EmulatedNowNs;
using hil::preload::Wait;

// Sleeps until emulated `deadline_ns`: 0, EINTR (with the time left in `rem`), or -1 when
// unmanaged (the caller sleeps the real way).
int SleepUntil(std::int64_t deadline_ns, timespec* rem) {
  const long r = Wait(nullptr, nullptr, deadline_ns);
  if (r == hil::preload::kUnmanaged) return -1;
  if (r == hil::preload::kInterrupted) {
    if (rem) *rem = hil::preload::ToTimespec(deadline_ns - EmulatedNowNs());
    return EINTR;
  }
  return 0;
}

bool BadTimespec(const timespec* ts) {
  return !ts || ts->tv_nsec < 0 || ts->tv_nsec >= 1'000'000'000 || ts->tv_sec < 0;
}

}  // namespace

extern "C" {

int nanosleep(const timespec* req, timespec* rem) {
  if (!hil::preload::SharedState()) return hil::preload::Real().nanosleep(req, rem);
  if (BadTimespec(req)) {
    errno = EINVAL;
    return -1;
  }
  const int r = SleepUntil(EmulatedNowNs() + hil::preload::ToNs(*req), rem);
  if (r < 0) return hil::preload::Real().nanosleep(req, rem);
  if (r == 0) return 0;
  errno = r;
  return -1;
}

int clock_nanosleep(clockid_t clock, int flags, const timespec* req, timespec* rem) {
  if (!hil::preload::Emulated(clock))
    return hil::preload::Real().clock_nanosleep(clock, flags, req, rem);
  if (BadTimespec(req)) return EINVAL;
  const std::int64_t deadline = (flags & TIMER_ABSTIME) != 0
                                    ? hil::preload::EmulatedTimeOf(clock, hil::preload::ToNs(*req))
                                    : EmulatedNowNs() + hil::preload::ToNs(*req);
  const int r = SleepUntil(deadline, (flags & TIMER_ABSTIME) != 0 ? nullptr : rem);
  if (r < 0) return hil::preload::Real().clock_nanosleep(clock, flags, req, rem);
  return r;
}

int usleep(useconds_t us) {
  if (!hil::preload::SharedState()) return hil::preload::Real().usleep(us);
  const int r = SleepUntil(EmulatedNowNs() + static_cast<std::int64_t>(us) * 1000, nullptr);
  if (r < 0) return hil::preload::Real().usleep(us);
  if (r == 0) return 0;
  errno = r;
  return -1;
}

unsigned sleep(unsigned s) {
  if (!hil::preload::SharedState()) return hil::preload::Real().sleep(s);
  const std::int64_t deadline = EmulatedNowNs() + static_cast<std::int64_t>(s) * 1'000'000'000;
  timespec rem{};
  const int r = SleepUntil(deadline, &rem);
  if (r < 0) return hil::preload::Real().sleep(s);
  if (r == 0) return 0;
  return static_cast<unsigned>(rem.tv_sec + (rem.tv_nsec > 0 ? 1 : 0));
}

}  // extern "C"

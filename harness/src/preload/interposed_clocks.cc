// The clocks a program reads, on hil's emulated time (README.md): clock_gettime for the
// REALTIME, MONOTONIC and BOOTTIME clocks (and their COARSE and RAW variants), gettimeofday,
// time and timespec_get. Other clocks (CPU time, TAI) are the real ones.
#include <time.h>

#include <sys/time.h>

#include "preload_state.h"

using hil::preload::ClockReadingNs;
using hil::preload::Emulated;
using hil::preload::EmulatedNowNs;
using hil::preload::Real;
using hil::preload::ToTimespec;

extern "C" {

int clock_gettime(clockid_t clock, timespec* ts) noexcept {
  if (!Emulated(clock)) return Real().clock_gettime(clock, ts);
  *ts = ToTimespec(ClockReadingNs(clock, EmulatedNowNs()));
  return 0;
}

int gettimeofday(timeval* tv, void* tz) noexcept {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  // glibc declares tv non-null; programs pass null all the same (only the zone wanted): a
  // volatile copy keeps the compiler from taking the declaration's word for it
  timeval* volatile out = tv;
  if (out != nullptr) {
    out->tv_sec = ts.tv_sec;
    out->tv_usec = ts.tv_nsec / 1000;
  }
  if (tz) {
    auto* z = static_cast<struct timezone*>(tz);
    z->tz_minuteswest = 0;
    z->tz_dsttime = 0;
  }
  return 0;
}

time_t time(time_t* t) noexcept {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  if (t) *t = ts.tv_sec;
  return ts.tv_sec;
}

int timespec_get(timespec* ts, int base) noexcept {
  if (base != TIME_UTC) return 0;
  clock_gettime(CLOCK_REALTIME, ts);
  return base;
}

}  // extern "C"

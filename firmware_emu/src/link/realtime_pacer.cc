#include "hil/firmware_emu/link/realtime_pacer.h"

#include <sched.h>
#include <time.h>

#include <cmath>

#include <sys/prctl.h>

namespace hil::link {
namespace {

constexpr std::int64_t kBusyWaitNs = 60000;  // spin over the last 60 µs

}  // namespace

RealtimePacer::RealtimePacer(double speed) : speed_(speed), wall_start_ns_(MonotonicNs()) {}

std::int64_t RealtimePacer::MonotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

std::int64_t RealtimePacer::WallNsOf(Time t) const {
  return wall_start_ns_ +
         static_cast<std::int64_t>(std::llround(static_cast<double>(ToNs(t)) / speed_));
}

Time RealtimePacer::SimTimeOfWall(std::int64_t wall_ns) const {
  return TimeFromNs(static_cast<std::int64_t>(
      std::llround(static_cast<double>(wall_ns - wall_start_ns_) * speed_)));
}

std::int64_t RealtimePacer::SleepUntil(Time t) const {
  const std::int64_t target = WallNsOf(t);
  std::int64_t now = MonotonicNs();
  if (target - now > kBusyWaitNs) {
    const std::int64_t wake = target - kBusyWaitNs;
    timespec ts{static_cast<time_t>(wake / 1000000000LL), static_cast<long>(wake % 1000000000LL)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
    }
  }
  while ((now = MonotonicNs()) < target) {
  }
  return now;
}

bool RealtimePacer::RequestRealtimeScheduling() {
  prctl(PR_SET_TIMERSLACK, 1UL, 0, 0, 0);
  sched_param param{};
  param.sched_priority = 50;
  return sched_setscheduler(0, SCHED_FIFO, &param) == 0;
}

}  // namespace hil::link

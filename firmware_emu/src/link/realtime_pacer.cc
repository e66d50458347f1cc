#include "hil/firmware_emu/link/realtime_pacer.h"

#include <pthread.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include <sys/prctl.h>
#include <sys/resource.h>

namespace hil::link {

RealtimePacer::RealtimePacer(double speed) : speed_(speed), wall_start_(WallNow()) {}

WallTime RealtimePacer::WallTimeOf(Time t) const {
  return wall_start_ +
         Duration{static_cast<std::int64_t>(std::llround(static_cast<double>(ToNs(t)) / speed_))};
}

Time RealtimePacer::SimTimeOfWall(WallTime wall) const {
  return TimeFromNs(static_cast<std::int64_t>(
      std::llround(static_cast<double>((wall - wall_start_).count()) * speed_)));
}

// The last stretch (kSpin) is spun, the rest slept (an absolute CLOCK_MONOTONIC timer, the thread's
// slack: 0 for a real-time thread). A SCHED_FIFO thread that spun the last 60 µs (the pacing
// thread: 100 µs) before each byte used 8.6 % of a CPU in seed000's real-time run (issue 40.9); 30
// µs is about the wake-up latency of a loaded machine (cyclictest p50 32-39 µs here), so the spin
// is mostly what the wake-up left, and a quiet machine spends at most 30 µs a byte.
WallTime RealtimePacer::SleepUntil(Time t) const {
  const WallTime target = WallTimeOf(t);
  WallTime now = WallNow();
  if (target - now > kSpin) {
    const std::int64_t wake_ns = ToNs(target - kSpin);
    const timespec ts{static_cast<time_t>(wake_ns / 1000000000LL),
                      static_cast<long>(wake_ns % 1000000000LL)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
    }
  }
  while ((now = WallNow()) < target) {
  }
  return now;
}

ThreadCpuReading ThreadCpuReading::Now() {
  ThreadCpuReading r;
  rusage u{};
  if (getrusage(RUSAGE_THREAD, &u) == 0) {
    r.user_s =
        static_cast<double>(u.ru_utime.tv_sec) + static_cast<double>(u.ru_utime.tv_usec) * 1e-6;
    r.system_s =
        static_cast<double>(u.ru_stime.tv_sec) + static_cast<double>(u.ru_stime.tv_usec) * 1e-6;
  }
  r.wall = WallNow();
  return r;
}

ThreadUsage ThreadCpuReading::Since(const ThreadCpuReading& start) const {
  return {user_s - start.user_s, system_s - start.system_s, ToSeconds(wall - start.wall)};
}

ThreadSchedule RealtimePacer::CurrentThreadSchedule() {
  ThreadSchedule s;
  int policy = 0;
  sched_param param{};
  if (pthread_getschedparam(pthread_self(), &policy, &param) == 0) {
    s.policy = policy == SCHED_FIFO    ? "SCHED_FIFO"
               : policy == SCHED_RR    ? "SCHED_RR"
               : policy == SCHED_OTHER ? "SCHED_OTHER"
               : policy == SCHED_BATCH ? "SCHED_BATCH"
               : policy == SCHED_IDLE  ? "SCHED_IDLE"
                                       : "policy " + std::to_string(policy);
    s.priority = param.sched_priority;
  }
  const int slack = prctl(PR_GET_TIMERSLACK, 0, 0, 0, 0);
  s.timer_slack_ns = slack;
  s.tid = static_cast<int>(gettid());
  return s;
}

ThreadSchedule RealtimePacer::RequestRealtimeScheduling(int priority) {
  prctl(PR_SET_TIMERSLACK, 1UL, 0, 0, 0);
  sched_param param{};
  param.sched_priority = priority;
  const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
  ThreadSchedule s = CurrentThreadSchedule();
  if (err != 0) s.refused = std::strerror(err);
  return s;
}

}  // namespace hil::link

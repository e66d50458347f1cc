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
namespace {

// The last stretch is spun, the rest slept (an absolute CLOCK_MONOTONIC timer, the thread's slack:
// 0 for a real-time thread). A SCHED_FIFO thread that spun the last 60 µs (the pacing thread: 100
// µs) before each byte used 8.6 % of a CPU in seed000's real-time run (issue 40.9); 30 µs is about
// the wake-up latency of a loaded machine (cyclictest p50 32-39 µs here), so the spin is mostly
// what the wake-up left, and a quiet machine spends at most 30 µs a byte.
constexpr std::int64_t kSpinNs = RealtimePacer::kSpinNs;

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
  if (target - now > kSpinNs) {
    const std::int64_t wake = target - kSpinNs;
    const timespec ts{static_cast<time_t>(wake / 1000000000LL),
                      static_cast<long>(wake % 1000000000LL)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {
    }
  }
  while ((now = MonotonicNs()) < target) {
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
  r.wall_ns = RealtimePacer::MonotonicNs();
  return r;
}

ThreadUsage ThreadCpuReading::Since(const ThreadCpuReading& start) const {
  return {user_s - start.user_s, system_s - start.system_s,
          static_cast<double>(wall_ns - start.wall_ns) * 1e-9};
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

#pragma once
/// @file
/// What the machine gave a real-time run (issue 15.10): the CPU time the kernel counted in
/// /proc/stat between two moments (busy, idle and steal, the time a hypervisor ran other guests
/// on our virtual CPUs), the online CPUs, the load average and the real-time throttling limits.
/// schedule_error.json records them beside the pacing threads' policies, so that a schedule error
/// can be read against what was possible.

#include <cstdint>
#include <optional>
#include <string>

namespace hil::harness {

/// The aggregate "cpu" line of /proc/stat, in clock ticks (USER_HZ).
struct CpuTicks {
  std::uint64_t user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0,
                steal = 0;
  std::uint64_t total() const {
    return user + nice + system + idle + iowait + irq + softirq + steal;
  }
};

/// Parses the aggregate "cpu " line of a /proc/stat text; nullopt when there is none.
std::optional<CpuTicks> ParseProcStat(const std::string& text);
/// /proc/stat now; nullopt when it cannot be read.
std::optional<CpuTicks> ReadCpuTicks();

/// Shares of the CPU time between two readings, in percent of all CPUs' time.
struct CpuShares {
  double busy_pct = 0, idle_pct = 0, steal_pct = 0;
  std::uint64_t ticks = 0;  ///< all CPUs' ticks between the readings
};
CpuShares SharesBetween(const CpuTicks& from, const CpuTicks& to);

/// The machine's figures for a real-time run's report.
struct MachineFigures {
  long cpus_online = 0;
  double load_1m = 0, load_5m = 0, load_15m = 0;
  /// /proc/sys/kernel/sched_rt_runtime_us and _period_us (-1: unlimited; nullopt: unreadable)
  std::optional<long> rt_runtime_us, rt_period_us;
  /// uname's release and version (the version names the preemption build, e.g. PREEMPT_DYNAMIC)
  std::string kernel;
  /// The preemption model in use: debugfs sched/preempt when readable, else a preempt= on the
  /// kernel command line, else empty (the build's default: CONFIG_PREEMPT_* in /proc/config.gz)
  std::string preempt;
};
MachineFigures ReadMachineFigures();

/// The CPU's model name (the first `model name` of /proc/cpuinfo, e.g. "AMD EPYC 7B13"), or the
/// machine's architecture (uname) when /proc/cpuinfo names none (some ARM kernels).
std::string ReadCpuModel();

}  // namespace hil::harness

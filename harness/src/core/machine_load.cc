#include "hil/harness/core/machine_load.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

#include <sys/utsname.h>

namespace hil::harness {
namespace {

std::string ReadText(const char* path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::optional<long> ReadLong(const char* path) {
  std::ifstream in(path);
  long v = 0;
  if (in >> v) return v;
  return std::nullopt;
}

}  // namespace

std::optional<CpuTicks> ParseProcStat(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("cpu ", 0) != 0) continue;
    std::istringstream f(line.substr(4));
    CpuTicks t;
    if (!(f >> t.user >> t.nice >> t.system >> t.idle)) return std::nullopt;
    // older kernels end the line early: the missing fields stay 0
    f >> t.iowait >> t.irq >> t.softirq >> t.steal;
    return t;
  }
  return std::nullopt;
}

std::optional<CpuTicks> ReadCpuTicks() { return ParseProcStat(ReadText("/proc/stat")); }

CpuShares SharesBetween(const CpuTicks& from, const CpuTicks& to) {
  CpuShares s;
  const auto diff = [](std::uint64_t a, std::uint64_t b) { return b > a ? b - a : 0; };
  s.ticks = diff(from.total(), to.total());
  if (s.ticks == 0) return s;
  const double total = static_cast<double>(s.ticks);
  const std::uint64_t idle = diff(from.idle + from.iowait, to.idle + to.iowait);
  const std::uint64_t steal = diff(from.steal, to.steal);
  s.idle_pct = 100.0 * static_cast<double>(idle) / total;
  s.steal_pct = 100.0 * static_cast<double>(steal) / total;
  s.busy_pct = 100.0 - s.idle_pct - s.steal_pct;
  return s;
}

MachineFigures ReadMachineFigures() {
  MachineFigures m;
  m.cpus_online = sysconf(_SC_NPROCESSORS_ONLN);
  std::istringstream load(ReadText("/proc/loadavg"));
  load >> m.load_1m >> m.load_5m >> m.load_15m;
  m.rt_runtime_us = ReadLong("/proc/sys/kernel/sched_rt_runtime_us");
  m.rt_period_us = ReadLong("/proc/sys/kernel/sched_rt_period_us");
  utsname u{};
  if (uname(&u) == 0) m.kernel = std::string(u.release) + " " + u.version;
  std::string preempt = ReadText("/sys/kernel/debug/sched/preempt");
  if (preempt.empty()) {
    std::istringstream cmdline(ReadText("/proc/cmdline"));
    for (std::string word; cmdline >> word;) {
      if (word.rfind("preempt=", 0) == 0) preempt = word;
    }
  }
  while (!preempt.empty() && (preempt.back() == '\n' || preempt.back() == ' ')) preempt.pop_back();
  m.preempt = preempt;
  return m;
}

std::string ReadCpuModel() {
  std::istringstream info(ReadText("/proc/cpuinfo"));
  for (std::string line; std::getline(info, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(colon + 1);
    while (!name.empty() && name.front() == ' ') name.erase(name.begin());
    if (!name.empty()) return name;
  }
  utsname u{};
  return uname(&u) == 0 ? std::string(u.machine) : "unknown";
}

}  // namespace hil::harness

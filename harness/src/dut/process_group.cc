#include "hil/harness/dut/process_group.h"

#include <dirent.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace hil::harness {
namespace {

/// State letter and process group of /proc/<path>/stat (state ' ' when unreadable).
struct StatFields {
  char state = ' ';
  long pgrp = -1;
};

StatFields ReadStat(const std::string& stat_path) {
  StatFields f;
  char buf[512];
  FILE* in = std::fopen(stat_path.c_str(), "re");
  if (!in) return f;
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, in);
  std::fclose(in);
  buf[n] = '\0';
  // "pid (comm) S ppid pgrp ...": comm may hold spaces and parentheses, so parse after the last ')'
  const char* close = std::strrchr(buf, ')');
  if (!close) return f;
  char state = ' ';
  long ppid = 0, pgrp = -1;
  if (std::sscanf(close + 1, " %c %ld %ld", &state, &ppid, &pgrp) != 3) return f;
  f.state = state;
  f.pgrp = pgrp;
  return f;
}

std::uint64_t ContextSwitches(const std::string& status_path) {
  std::ifstream in(status_path);
  std::string line;
  std::uint64_t n = 0;
  while (std::getline(in, line)) {
    if (line.rfind("voluntary_ctxt_switches:", 0) == 0 ||
        line.rfind("nonvoluntary_ctxt_switches:", 0) == 0) {
      n += std::strtoull(line.c_str() + line.find(':') + 1, nullptr, 10);
    }
  }
  return n;
}

template <typename F>
void ForEachNumericEntry(const std::string& dir, F&& f) {
  DIR* d = opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = readdir(d)) {
    if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
    f(std::string(e->d_name));
  }
  closedir(d);
}

}  // namespace

std::vector<int> LiveGroupMembers(int pgid) {
  std::vector<int> pids;
  if (pgid <= 0) return pids;
  ForEachNumericEntry("/proc", [&](const std::string& pid) {
    const StatFields f = ReadStat("/proc/" + pid + "/stat");
    if (f.pgrp == pgid && f.state != 'Z' && f.state != 'X' && f.state != ' ')
      pids.push_back(std::atoi(pid.c_str()));
  });
  return pids;
}

GroupActivity ReadGroupActivity(int pgid) {
  GroupActivity a;
  const std::vector<int> pids = LiveGroupMembers(pgid);
  if (pids.empty()) return a;
  a.readable = true;
  a.all_asleep = true;
  for (const int pid : pids) {
    const std::string task_dir = "/proc/" + std::to_string(pid) + "/task";
    ForEachNumericEntry(task_dir, [&](const std::string& tid) {
      const std::string base = task_dir + "/" + tid;
      const StatFields f = ReadStat(base + "/stat");
      if (f.state == ' ') return;  // the thread ended meanwhile
      ++a.threads;
      if (f.state != 'S') a.all_asleep = false;
      a.switches += ContextSwitches(base + "/status");
    });
  }
  if (a.threads == 0) a.readable = a.all_asleep = false;
  return a;
}

bool SleptThroughout(const GroupActivity& before, const GroupActivity& after) {
  return before.readable && after.readable && before.all_asleep && after.all_asleep &&
         before.threads == after.threads && before.switches == after.switches;
}

}  // namespace hil::harness

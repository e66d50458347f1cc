#include "hil/harness/dut/process_group.h"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

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
  // open, one read, close (stdio's fopen/fread cost two calls more, for every process of /proc)
  const int fd = open(stat_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return f;
  const ssize_t n = read(fd, buf, sizeof buf - 1);
  close(fd);
  if (n <= 0) return f;
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

char ThreadState(int pid, int tid) {
  return ReadStat("/proc/" + std::to_string(pid) + "/task/" + std::to_string(tid) + "/stat").state;
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

namespace {

/// State letter and thread count from the text of a stat file (state ' ' when it cannot be read).
/// The text of an open /proc file, read again from its start ("" when it cannot be read).
std::string ReadAgain(int fd) {
  char buf[512];
  const ssize_t n = fd >= 0 ? pread(fd, buf, sizeof buf, 0) : -1;
  return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
}

// Fields 3 (state) and 20 (num_threads) of proc(5)'s stat line, read by hand: the sleep probe
// parses one per host thread at every check of a host turn (sscanf's format parsing was a sixth
// of the probe's time).
StatFields ParseStateAndThreads(char* buf, long* threads) {
  StatFields f;
  const char* p = std::strrchr(buf, ')');
  if (!p) return f;
  const auto next_field = [&p] {
    while (*p == ' ') ++p;
    const char* start = p;
    while (*p != ' ' && *p != '\0' && *p != '\n') ++p;
    return p > start ? start : nullptr;
  };
  ++p;
  const char* state = next_field();
  if (!state) return f;
  const char* field = nullptr;
  for (int k = 4; k <= 20; ++k) {
    if (!(field = next_field())) return f;
  }
  char* end = nullptr;
  const long n = std::strtol(field, &end, 10);
  if (end == field) return f;
  *threads = n;
  f.state = *state;
  return f;
}

}  // namespace

GroupSleepProbe::~GroupSleepProbe() { CloseTasks(); }

void GroupSleepProbe::CloseTasks() {
  for (const Task& t : tasks_) {
    close(t.fd);
    if (t.children_fd >= 0) close(t.children_fd);
  }
  tasks_.clear();
}

void GroupSleepProbe::ReadTasks() {
  CloseTasks();
  for (const int pid : LiveGroupMembers(pgid_)) {
    const std::string task_dir = "/proc/" + std::to_string(pid) + "/task";
    ForEachNumericEntry(task_dir, [&](const std::string& tid) {
      const int fd = open((task_dir + "/" + tid + "/stat").c_str(), O_RDONLY | O_CLOEXEC);
      if (fd < 0) return;
      Task t;
      t.fd = fd;
      t.children_fd = open((task_dir + "/" + tid + "/children").c_str(), O_RDONLY | O_CLOEXEC);
      t.children = ReadAgain(t.children_fd);
      t.process = std::atoi(tid.c_str()) == pid;
      char buf[512];
      const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
      if (n > 0) {
        buf[n] = '\0';
        ParseStateAndThreads(buf, &t.threads);
      }
      tasks_.push_back(t);
    });
  }
}

bool GroupSleepProbe::AllAsleep() {
  if (pgid_ <= 0) return false;
  if (tasks_.empty()) ReadTasks();
  for (int attempt = 0; attempt < 2; ++attempt) {
    bool changed = false, live = false;
    for (const Task& t : tasks_) {
      char buf[512];
      const ssize_t n = pread(t.fd, buf, sizeof buf - 1, 0);
      long threads = 0;
      StatFields f;
      if (n > 0) {
        buf[n] = '\0';
        f = ParseStateAndThreads(buf, &threads);
      }
      if (f.state == ' ' || (t.process && threads != t.threads) ||
          (t.children_fd >= 0 && ReadAgain(t.children_fd) != t.children)) {
        changed = true;  // a thread ended or started, a process forked: read the list again
        break;
      }
      if (f.state == 'Z' || f.state == 'X') continue;
      if (f.state != 'S') return false;
      live = true;
    }
    if (!changed) return live;
    ReadTasks();
  }
  return false;
}

}  // namespace hil::harness

#include "hil/harness/run/run_priority.h"

#include <dirent.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <sys/resource.h>

namespace hil::harness {

RunPriority SetProcessNice(int nice) {
  RunPriority p;
  p.requested = nice;
  if (nice != 0) {
    // setpriority(PRIO_PROCESS, tid) sets one thread (Linux), so every task of /proc/self/task
    DIR* d = opendir("/proc/self/task");
    if (!d) {
      p.refused = std::string("/proc/self/task: ") + std::strerror(errno);
    } else {
      while (const dirent* e = readdir(d)) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        const auto tid = static_cast<id_t>(std::strtol(e->d_name, nullptr, 10));
        if (setpriority(PRIO_PROCESS, tid, nice) != 0 && p.refused.empty())
          p.refused = std::strerror(errno);
      }
      closedir(d);
    }
  }
  errno = 0;
  p.nice = getpriority(PRIO_PROCESS, 0);
  return p;
}

}  // namespace hil::harness

// How the programs under test hold hil's links, read from /proc (host_link_access.h).
#include "hil/harness/engine/host_link_access.h"

#include <fcntl.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace hil::harness {
namespace {

// Whether /proc/PID/fdinfo/FD says the descriptor was opened for writing (unreadable: yes).
bool OpenedForWriting(const std::string& fdinfo) {
  std::ifstream f(fdinfo);
  std::string key;
  while (f >> key) {
    if (key != "flags:") continue;
    std::string octal;
    f >> octal;
    const int flags = static_cast<int>(std::stol(octal, nullptr, 8));
    return (flags & O_ACCMODE) != O_RDONLY;
  }
  return true;
}

}  // namespace

bool LinksHeldReadOnly(const std::vector<int>& pids, const std::vector<SerialEndpoint*>& links) {
  std::vector<std::string> unheld;
  for (const SerialEndpoint* ep : links) {
    std::error_code ec;
    const auto target = std::filesystem::canonical(ep->link_path(), ec);
    if (ec) return false;
    unheld.push_back(target.string());
  }
  std::vector<std::string> devices = unheld;
  for (const int pid : pids) {
    const std::string proc = "/proc/" + std::to_string(pid);
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(proc + "/fd", ec)) {
      std::error_code ec2;
      const std::string target = std::filesystem::read_symlink(e.path(), ec2).string();
      if (ec2 || std::find(devices.begin(), devices.end(), target) == devices.end()) continue;
      if (OpenedForWriting(proc + "/fdinfo/" + e.path().filename().string())) return false;
      std::erase(unheld, target);
    }
    if (ec) return false;
  }
  return unheld.empty();
}

}  // namespace hil::harness

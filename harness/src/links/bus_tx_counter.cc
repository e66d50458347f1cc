#include "hil/harness/links/bus_tx_counter.h"

#include <fstream>

#include <sys/stat.h>

namespace hil::harness {

BusTxCounter::BusTxCounter(const std::string& iface, const std::string& sysfs)
    : path_(sysfs + "/class/net/" + iface + "/statistics/tx_packets") {
  struct stat st {};
  const std::string virtual_dir = sysfs + "/devices/virtual/net/" + iface;
  if (iface.empty() || iface.find('/') != std::string::npos) return;
  if (stat(virtual_dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return;
  base_ = Read();
}

std::optional<std::uint64_t> BusTxCounter::Read() const {
  std::ifstream in(path_);
  std::uint64_t n = 0;
  if (!(in >> n)) return std::nullopt;
  return n;
}

std::optional<std::uint64_t> BusTxCounter::SentSinceStart() const {
  if (!base_) return std::nullopt;
  const std::optional<std::uint64_t> now = Read();
  if (!now || *now < *base_) return std::nullopt;  // the interface was re-created meanwhile
  return *now - *base_;
}

}  // namespace hil::harness

// The preload library's cache of which of hil's links each descriptor is (descriptor_cache.h).
#include "descriptor_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <sys/stat.h>

#include "preload_state.h"

namespace hil::preload {
namespace lk = harness::lockstep;
namespace {

// per descriptor number: bumped before and after every close or replacement of it
std::atomic<std::uint32_t> g_generation[kCachedDescriptors];
// per descriptor number: (generation << 32) | (link index + 2) when known, else 0
std::atomic<std::uint64_t> g_entry[kCachedDescriptors];
bool g_enabled = false;  // until the constructor has read the environment: no cache

__attribute__((constructor)) void ReadSwitch() {
  const char* v = std::getenv("HIL_LOCKSTEP_FD_CACHE");
  g_enabled = !v || std::strcmp(v, "0") != 0;
}

// One fstat: -2 when it failed, -1 for a descriptor that is not one of hil's links, else its
// index.
int StatLinkIndex(lk::Shared& sh, int fd, int links) {
  sh.descriptor_lookups.fetch_add(1);
  struct stat st {};
  if (fstat(fd, &st) != 0) return -2;
  if (!S_ISCHR(st.st_mode)) return -1;
  for (int k = 0; k < links; ++k) {
    if (sh.link_rdev[k] == st.st_rdev) return k;
  }
  return -1;
}

}  // namespace

int LinkIndexOf(int fd) {
  lk::Shared* sh = SharedState();
  const int links = sh ? std::min(sh->link_count.load(), lk::kMaxLinks) : 0;
  if (links == 0) return -1;  // not published yet: any descriptor counts as another
  const bool cached = g_enabled && fd >= 0 && fd < kCachedDescriptors;
  if (!cached) return std::max(StatLinkIndex(*sh, fd, links), -1);
  const std::uint64_t generation = g_generation[fd].load();
  const std::uint64_t entry = g_entry[fd].load();
  if (entry != 0 && (entry >> 32) == generation) return static_cast<int>(entry & 0xffffffffu) - 2;
  const int k = StatLinkIndex(*sh, fd, links);
  if (k == -2) return -1;
  // a close or replacement since `generation` was read makes this entry stale at once
  g_entry[fd].store((generation << 32) | static_cast<std::uint64_t>(k + 2));
  return k;
}

void ForgetLink(int fd) {
  if (fd >= 0 && fd < kCachedDescriptors) g_generation[fd].fetch_add(1);
}

void ForgetLinks(unsigned first, unsigned last) {
  const unsigned end = std::min(last, static_cast<unsigned>(kCachedDescriptors - 1));
  for (unsigned fd = first; fd <= end; ++fd) g_generation[fd].fetch_add(1);
}

}  // namespace hil::preload

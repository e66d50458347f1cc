#include "hil/harness/engine/virtual_gate.h"

#include <fcntl.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <sys/prctl.h>

namespace hil::harness {
namespace {

// A wait first yields the CPU a few times (the host, woken by the bytes, usually reads them
// within tens of microseconds), then sleeps in short steps that grow to 1 ms for a host that is
// busy or descheduled on a loaded machine.
constexpr int kYieldSteps = 16;
constexpr long kFirstSleepNs = 20'000;
constexpr long kLongestSleepNs = 1'000'000;

// Whether /proc/PID/fdinfo/FD says the descriptor was opened O_WRONLY or O_RDWR (unreadable:
// assumed so, the cautious answer).
bool OpenForWriting(const std::string& fdinfo) {
  std::FILE* f = std::fopen(fdinfo.c_str(), "r");
  if (!f) return true;
  unsigned long flags = O_RDWR;
  char line[128];
  while (std::fgets(line, sizeof line, f)) {
    if (std::sscanf(line, "flags: %lo", &flags) == 1) break;
  }
  std::fclose(f);
  return (flags & O_ACCMODE) != O_RDONLY;
}

void SleepNs(long ns) {
  timespec ts{0, ns};
  nanosleep(&ts, nullptr);
}

}  // namespace

VirtualGate::VirtualGate(std::vector<SerialEndpoint*> host_links,
                         std::size_t max_link_backlog_bytes, WaitStep on_wait, int host_pgid,
                         Duration max_skew)
    : max_backlog_(max_link_backlog_bytes), on_wait_(std::move(on_wait)), max_skew_(max_skew) {
  for (const SerialEndpoint* ep : host_links) links_.push_back({ep, 0});
  if (host_pgid > 0) host_.emplace(host_pgid);
  host_pgid_ = host_pgid;
  // short sleeps mean short sleeps: the default timer slack (50 µs) would stretch every step
  prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
}

bool VirtualGate::Reads(const SerialEndpoint& ep) const {
  for (const Link& l : links_) {
    if (l.ep == &ep) return l.read;
  }
  return false;
}

void VirtualGate::StopReading(const SerialEndpoint& ep) {
  // marked, not erased: a wait in progress may hold a pointer to any link
  for (Link& l : links_) {
    if (l.ep != &ep) continue;
    l.read = false;
    l.unread_bound = l.seen_unread = 0;
    l.runs.clear();
  }
}

VirtualGate::Link* VirtualGate::Find(const SerialEndpoint& ep) {
  for (Link& l : links_) {
    if (l.ep == &ep) return l.read ? &l : nullptr;
  }
  return nullptr;
}

void VirtualGate::Ask(Link& l) {
  // The kernel's count (FIONREAD) is the line discipline's: at most 4095 bytes, and without the
  // bytes still in the pty's flip buffers (those beyond what the line discipline holds, or a
  // write its worker has not handed over yet). Only its 0 is exact (PendingToHost hands over
  // what is in flight first): any other count is a lower bound, and the bound of what is unread
  // stays until the host has read everything. (Taken for the count, a backlog of 16 KB looked
  // like 4 KB: more went in than the pty holds, and the write stalled.)
  l.seen_unread = l.ep->PendingToHost();
  if (l.seen_unread == 0) l.unread_bound = 0;
  l.unread_bound = std::max(l.unread_bound, l.seen_unread);
}

std::size_t VirtualGate::Refresh(const Link* except, const Link* only, bool ask_all) {
  std::size_t unread = 0;
  for (Link& l : links_) {
    if (!l.read || &l == except || (only && &l != only) || (l.unread_bound == 0 && !ask_all))
      continue;
    Ask(l);
    unread += l.unread_bound;
  }
  return unread;
}

bool VirtualGate::Wait(const std::function<bool()>& done, const Link* except, const Link* only) {
  long sleep_ns = kFirstSleepNs;
  for (int step = 0;; ++step) {
    if (done()) return true;
    std::size_t unread = 0;
    for (const Link& l : links_) {
      if (l.read && &l != except && (!only || &l == only)) unread += l.seen_unread;
    }
    if (!on_wait_(unread, step == 0)) return false;
    if (step < kYieldSteps) {
      sched_yield();
    } else {
      SleepNs(sleep_ns);
      sleep_ns = std::min(sleep_ns * 2, kLongestSleepNs);
    }
  }
}

bool VirtualGate::OthersReadUpTo(const Link* self, Time t) {
  for (Link& l : links_) {
    if (&l == self || !l.read) continue;
    if (l.runs.empty() || l.runs.front().second > t) continue;
    // ask the kernel how far the host has read, and forget the runs it has read entirely
    Ask(l);
    const std::size_t read = l.written - std::min(l.unread_bound, l.written);
    while (!l.runs.empty() && l.runs.front().first <= read) l.runs.pop_front();
    if (!l.runs.empty() && l.runs.front().second <= t) return false;
  }
  return true;
}

void VirtualGate::Counted(Link& self, std::size_t bytes, Time t_first) {
  self.unread_bound += bytes;
  self.seen_unread += bytes;
  if (max_skew_ <= Duration{0}) return;
  self.written += bytes;
  self.runs.emplace_back(self.written, t_first);
}

bool VirtualGate::BeforeWrite(const SerialEndpoint& ep, std::size_t bytes, Time t_first,
                              Time t_last) {
  Link* self = Find(ep);
  if (!self) return true;  // a link the host does not read: no order to keep
  // every other link read to its last byte (or, with a max_skew, up to t_last − max_skew)
  const bool others_read =
      max_skew_ > Duration{0}
          ? Wait([&] { return OthersReadUpTo(self, t_last - max_skew_); }, self, nullptr)
          : Wait([&] { return Refresh(self, nullptr) == 0; }, self, nullptr);
  if (!others_read) return false;
  // this link's backlog below the bound (a message longer than the bound waits for an empty link)
  if (self->unread_bound + bytes > max_backlog_) {
    const auto room = [&] {
      Refresh(nullptr, self);
      return self->unread_bound == 0 || self->unread_bound + bytes <= max_backlog_;
    };
    if (!Wait(room, nullptr, self)) return false;
  }
  Counted(*self, bytes, t_first);
  return true;
}

bool VirtualGate::TryWrite(const SerialEndpoint& ep, std::size_t bytes, Time t_first, Time t_last) {
  Link* self = Find(ep);
  if (!self) return true;
  if (max_skew_ > Duration{0}) {
    const WallTime now = WallNow();
    if (now - self->refused_at < kRetryAfterRefusal) return false;
    if (!OthersReadUpTo(self, t_last - max_skew_)) {
      self->refused_at = now;
      return false;
    }
  } else if (Refresh(self, nullptr) != 0) {
    return false;
  }
  if (self->unread_bound + bytes > max_backlog_) {
    Refresh(nullptr, self);
    if (self->unread_bound != 0 && self->unread_bound + bytes > max_backlog_) return false;
  }
  Counted(*self, bytes, t_first);
  return true;
}

bool VirtualGate::WaitForRoom(const std::function<std::size_t()>& write_more) {
  // as Wait, but the progress the watchdog sees is the bytes still to write
  std::size_t left = write_more();
  long sleep_ns = kFirstSleepNs;
  for (int step = 0; left > 0; ++step) {
    if (!on_wait_(left, step == 0)) return false;
    if (step < kYieldSteps) {
      sched_yield();
    } else {
      SleepNs(sleep_ns);
      sleep_ns = std::min(sleep_ns * 2, kLongestSleepNs);
    }
    left = write_more();
  }
  return true;
}

bool VirtualGate::WaitAllRead() {
  return Wait([&] { return Refresh(nullptr, nullptr) == 0; }, nullptr, nullptr);
}

std::size_t VirtualGate::Unread() { return Refresh(nullptr, nullptr, true); }

VirtualGate::LinkHolding VirtualGate::ScanHostLinks() const {
  std::vector<std::string> devices;
  for (const Link& l : links_) {
    if (!l.read) continue;
    std::error_code ec;
    const auto target = std::filesystem::canonical(l.ep->link_path(), ec);
    if (!ec) devices.push_back(target.string());
  }
  std::vector<std::string> unheld = devices;
  bool writable = false;
  for (const int pid : LiveGroupMembers(host_pgid_)) {
    std::error_code ec;
    const std::string proc = "/proc/" + std::to_string(pid);
    for (const auto& e : std::filesystem::directory_iterator(proc + "/fd", ec)) {
      std::error_code ec2;
      const std::string target = std::filesystem::read_symlink(e.path(), ec2).string();
      if (ec2 || std::find(devices.begin(), devices.end(), target) == devices.end()) continue;
      std::erase(unheld, target);
      writable = writable || OpenForWriting(proc + "/fdinfo/" + e.path().filename().string());
    }
  }
  return {unheld.empty(), writable};
}

void VirtualGate::NoteHostWrote() {
  if (!HostReadsOnly()) return;
  host_writes_ = true;
  std::fprintf(stderr,
               "hil: the estimator wrote to a link although it held them all read-only at its "
               "first turn: from now on every host turn waits for it (the turn that read these "
               "bytes depended on the machine)\n");
}

bool VirtualGate::WaitHostIdle() {
  if (!host_ || busy_host_) return WaitAllRead();
  const WallTime start = WallNow();
  std::optional<WallTime> all_read_since;
  WallTime last_scan = start - kHostScanPeriod;
  const auto idle = [&] {
    // a link found read with nothing written since stays read: only the others are asked
    if (Refresh(nullptr, nullptr) != 0) {
      all_read_since.reset();
      return false;
    }
    if (!links_opened_) {
      // a scan of /proc for the host's descriptors at most every kHostScanPeriod: the host
      // is starting, and needs the CPU more than this wait does
      const WallTime now = WallNow();
      if (now - last_scan < kHostScanPeriod) return false;
      last_scan = now;
      links_opened_ = ScanHostLinks().all_held || now - start > kHostStartLimit;
      if (!links_opened_) return false;
    }
    // every byte read: the host has been running since; asleep now, it has finished with them
    if (host_->AllAsleep()) return true;
    const WallTime now = WallNow();
    if (!all_read_since) all_read_since = now;
    if (now - *all_read_since < kBusyHostLimit) return false;
    busy_host_ = true;
    std::fprintf(stderr,
                 "hil: the estimator read all its input but did not sleep for %.0f s: it is never "
                 "waited for again, and the bytes it writes get the emulated time they are seen "
                 "at\n",
                 ToSeconds(kBusyHostLimit));
    return true;
  };
  if (!Wait(idle, nullptr, nullptr)) return false;
  // the first turn ended with the host asleep after its start-up: whether it can write at all
  if (!writes_scanned_ && !busy_host_) host_writes_ = ScanHostLinks().writable;
  writes_scanned_ = true;
  return true;
}

}  // namespace hil::harness

#include "hil/harness/lockstep/lockstep_host.h"

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <stdexcept>

#include <linux/futex.h>
#include <sys/mman.h>
#include <sys/syscall.h>

#include "hil/harness/lockstep/lockstep_advance.h"
#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness::lockstep {
namespace {

// Whether thread `tid` of process `pid` still exists and is not a zombie.
bool ThreadAlive(int pid, int tid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/task/" + std::to_string(tid) + "/stat");
  std::string stat;
  if (!std::getline(f, stat)) return false;
  const std::size_t paren = stat.rfind(')');
  if (paren == std::string::npos || paren + 2 >= stat.size()) return false;
  const char state = stat[paren + 2];
  return state != 'Z' && state != 'X';
}

bool SlotIdle(const ThreadSlot& s) {
  return s.tid.load() == 0 || (s.state.load() == kWaiting && s.acked.load() == s.seq.load());
}

long FutexWake(std::atomic<std::uint32_t>* word) {
  return syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(word), FUTEX_WAKE, INT_MAX, nullptr,
                 nullptr, 0);
}

}  // namespace

LockstepHost::LockstepHost(std::string path, std::int64_t utc_epoch_ns) : path_(std::move(path)) {
  const int fd = open(path_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0 || ftruncate(fd, sizeof(Shared)) != 0) {
    const std::string err = std::strerror(errno);
    if (fd >= 0) close(fd);
    throw std::runtime_error("cannot make the lockstep file " + path_ + ": " + err);
  }
  void* m = mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (m == MAP_FAILED)
    throw std::runtime_error("cannot map the lockstep file " + path_ + ": " + std::strerror(errno));
  // the file is zeros: every atomic starts at 0, every slot free
  shared_ = static_cast<Shared*>(m);
  shared_->utc_epoch_ns = utc_epoch_ns;
  shared_->version = kVersion;
  std::atomic_thread_fence(std::memory_order_seq_cst);
  shared_->magic = kMagic;
}

LockstepHost::~LockstepHost() {
  munmap(shared_, sizeof(Shared));
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

void LockstepHost::SetNow(Time t) { shared_->now_ns.store((t - Time{}).count()); }

Time LockstepHost::now() const { return Time{} + Duration(shared_->now_ns.load()); }

void LockstepHost::SetLinks(const std::vector<std::uint64_t>& rdevs) {
  const int n = static_cast<int>(std::min<std::size_t>(rdevs.size(), kMaxLinks));
  for (int k = 0; k < n; ++k) shared_->link_rdev[k] = rdevs[static_cast<std::size_t>(k)];
  shared_->link_count.store(n);
}

void LockstepHost::Grant(int i) {
  ThreadSlot& s = shared_->slots[i];
  s.seq.fetch_add(1);
  FutexWake(&s.seq);
}

void LockstepHost::Wake() {
  ++stats_.grants;
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  for (int i = 0; i < used; ++i) {
    if (shared_->slots[i].tid.load() != 0) Grant(i);
  }
}

void LockstepHost::Wake(Time t, std::uint64_t touched) {
  ++stats_.grants;
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  for (int i = 0; i < used; ++i) {
    if (Concerns(i, t, touched)) Grant(i);
  }
}

std::size_t LockstepHost::Busy() const {
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  std::size_t busy = 0;
  for (int i = 0; i < used; ++i) busy += SlotIdle(shared_->slots[i]) ? 0 : 1;
  return busy;
}

bool LockstepHost::Idle() const { return Busy() == 0; }

void LockstepHost::ForgetDeadThreads() {
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  for (int i = 0; i < used; ++i) {
    ThreadSlot& s = shared_->slots[i];
    const std::int32_t tid = s.tid.load();
    if (tid == 0 || ThreadAlive(s.pid.load(), tid)) continue;
    s.state.store(kRunning);
    s.tid.store(0);
    slots_freed_ = true;  // what it wrote before it died is read at the next turn
  }
}

bool LockstepHost::TakeHostWrites() {
  const std::uint64_t writes = shared_->host_writes.load();
  if (writes == writes_seen_ && !slots_freed_) return false;
  writes_seen_ = writes;
  slots_freed_ = false;
  return true;
}

bool LockstepHost::WaitIdle(const WaitStep& on_wait) {
  return WaitUntil(
      on_wait, [this] { return Idle(); }, false);
}

bool LockstepHost::WaitUntil(const WaitStep& on_wait, const std::function<bool()>& done,
                             bool move_clock_when_idle) {
  if (done()) return true;
  const WallTime start = WallNow();
  WallTime next_step = start + kStep;
  bool new_wait = true;
  shared_->hil_waiting.store(1);
  bool reached = false;
  while (!reached) {
    const std::uint32_t seen = shared_->host_wake.load();
    if (done()) {
      reached = true;
      break;
    }
    // idle, and no thread moved the clock (one ended, or its move is under way): hil does
    if (move_clock_when_idle && AllSlotsIdle(*shared_)) MoveClock();
    // sleeps until a thread waits or acknowledges (or the step's time has come)
    const timespec step{0, static_cast<long>(kStep.count())};
    ++stats_.slept;
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&shared_->host_wake), FUTEX_WAIT, seen,
            &step, nullptr, 0);
    const WallTime now = WallNow();
    if (now < next_step) continue;
    next_step = now + kStep;
    if (now - start >= kLivenessCheck) ForgetDeadThreads();
    if (!on_wait(Busy(), new_wait)) break;
    new_wait = false;
  }
  shared_->hil_waiting.store(0);
  stats_.wait += WallNow() - start;
  return reached;
}

bool LockstepHost::Concerns(int i, Time t, std::uint64_t touched) const {
  const ThreadSlot& s = shared_->slots[i];
  if (s.tid.load() == 0) return false;
  if (!SlotIdle(s) || s.deadline_ns.load() <= (t - Time{}).count()) return true;
  return s.on_descriptors.load() != 0 && (s.links.load() & touched) != 0;
}

bool LockstepHost::NeedsWake(Time t, std::uint64_t touched) const {
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  for (int i = 0; i < used; ++i) {
    if (Concerns(i, t, touched)) return true;
  }
  return false;
}

std::optional<Time> LockstepHost::EarliestDeadline() const {
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  std::int64_t earliest = kNoDeadline;
  for (int i = 0; i < used; ++i) {
    const ThreadSlot& s = shared_->slots[i];
    if (s.tid.load() == 0 || s.state.load() != kWaiting) continue;
    earliest = std::min(earliest, s.deadline_ns.load());
  }
  if (earliest == kNoDeadline) return std::nullopt;
  return Time{} + Duration(earliest);
}

void LockstepHost::Abandon() {
  shared_->passthrough.store(1);
  Wake();
  --stats_.grants;  // a wake to let go, not a turn
}

namespace {
// 'text' for /bin/sh: single quotes, each ' in it as '\''.
std::string ShellQuoted(const std::string& text) {
  std::string q = "'";
  for (const char ch : text) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}
}  // namespace

std::string LockstepHost::ShellExports(const std::string& library) const {
  // A program built with AddressSanitizer (gcc links its runtime dynamically) aborts at start when
  // a preloaded library comes before the runtime, unless told not to check: the library only
  // interposes the clock, sleep and poll calls and forwards them to the next definition (the
  // sanitizer's interceptors included), so the order is harmless. Other programs ignore the option.
  return "LD_PRELOAD=" + ShellQuoted(library) + "${LD_PRELOAD:+:$LD_PRELOAD} " + kEnvFile + "=" +
         ShellQuoted(path_) +
         " ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0;"
         " export LD_PRELOAD ASAN_OPTIONS " +
         kEnvFile + "; ";
}

std::vector<LockstepHost::Process> LockstepHost::Processes() const {
  std::vector<Process> out;
  const int used = std::min(shared_->processes_used.load(), kMaxProcesses);
  for (int i = 0; i < used; ++i) {
    const ProcessEntry& p = shared_->processes[i];
    if (p.pid.load() == 0) continue;
    out.push_back({p.pid.load(), std::string(p.comm, strnlen(p.comm, sizeof p.comm))});
  }
  return out;
}

LockstepHost::Stats LockstepHost::stats() const {
  Stats s = stats_;
  s.grants += shared_->advances.load();  // the programs' own moves of the clock
  s.descriptor_lookups = shared_->descriptor_lookups.load();
  const int used = std::min(shared_->slots_used.load(), kMaxThreads);
  for (int i = 0; i < used; ++i) {
    s.thread_waits += shared_->slots[i].waits.load();
    s.thread_looks += shared_->slots[i].looks.load();
  }
  return s;
}

std::string FindPreloadLibrary() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  for (const auto& p :
       {exe.parent_path() / "libhil_lockstep.so",
        exe.parent_path().parent_path() / "lib" / "hil" / "preload" / "libhil_lockstep.so"}) {
    if (std::filesystem::exists(p, ec)) return p.string();
  }
  return "";
}

}  // namespace hil::harness::lockstep

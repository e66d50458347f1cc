// The preload library's state: the shared file, the real functions, the threads' slots, the wait.
#include "preload_state.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>

#include <linux/futex.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/syscall.h>

#include "hil/harness/lockstep/lockstep_advance.h"

#include "descriptor_cache.h"

namespace hil::preload {
namespace lk = harness::lockstep;
namespace {

lk::Shared* g_shared = nullptr;
RealFunctions g_real{};
bool g_resolved = false;
pthread_key_t g_slot_key;
// the calling thread's slot (initial-exec: no allocation on first use in a preloaded library)
__attribute__((tls_model("initial-exec"))) thread_local lk::ThreadSlot* t_slot = nullptr;
// this process's /proc/self/io (its `syscw`: write calls of all its threads), -1: none
int g_io_fd = -1;
// the count the calling thread saw at its last wait, and whether it closed, shut down or sent
// since (NoteTouched)
__attribute__((tls_model("initial-exec"))) thread_local std::uint64_t t_syscw = 0;
__attribute__((tls_model("initial-exec"))) thread_local bool t_touched = true;

template <class F>
void Resolve(F& f, const char* name) {
  f = reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

void ResolveAll() {
  Resolve(g_real.clock_gettime, "clock_gettime");
  Resolve(g_real.nanosleep, "nanosleep");
  Resolve(g_real.clock_nanosleep, "clock_nanosleep");
  Resolve(g_real.usleep, "usleep");
  Resolve(g_real.sleep, "sleep");
  Resolve(g_real.poll, "poll");
  Resolve(g_real.ppoll, "ppoll");
  Resolve(g_real.select, "select");
  Resolve(g_real.pselect, "pselect");
  Resolve(g_real.epoll_wait, "epoll_wait");
  Resolve(g_real.epoll_pwait, "epoll_pwait");
  Resolve(g_real.read, "read");
  Resolve(g_real.close, "close");
  Resolve(g_real.shutdown, "shutdown");
  Resolve(g_real.send, "send");
  Resolve(g_real.sendto, "sendto");
  Resolve(g_real.sendmsg, "sendmsg");
  Resolve(g_real.ioctl, "ioctl");
  Resolve(g_real.dup2, "dup2");
  Resolve(g_real.dup3, "dup3");
  Resolve(g_real.close_range, "close_range");
  Resolve(g_real.closefrom, "closefrom");
  Resolve(g_real.fclose, "fclose");
  Resolve(g_real.freopen, "freopen");
  Resolve(g_real.freopen64, "freopen64");
  Resolve(g_real.pclose, "pclose");
  Resolve(g_real.fcloseall, "fcloseall");
  Resolve(g_real.closedir, "closedir");
  Resolve(g_real.daemon, "daemon");
  g_resolved = true;
}

long Futex(std::atomic<std::uint32_t>* word, int op, std::uint32_t val) {
  return syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(word), op, val, nullptr, nullptr, 0);
}

void NotifyHil() {
  g_shared->host_wake.fetch_add(1);
  if (g_shared->hil_waiting.load() != 0) Futex(&g_shared->host_wake, FUTEX_WAKE, INT_MAX);
}

// A thread that has acknowledged wakes hil only when that made the programs idle: hil wants
// nothing else (each wake it got before cost a context switch both ways, several a turn). Every
// access is sequentially consistent, so of threads that acknowledge at the same time the last
// one sees the others' acknowledgements and wakes hil; hil's wait has a timeout besides.
void NotifyHilIfIdle() {
  g_shared->host_wake.fetch_add(1);
  if (g_shared->hil_waiting.load() != 0 && lk::AllSlotsIdle(*g_shared))
    Futex(&g_shared->host_wake, FUTEX_WAKE, INT_MAX);
}

void OpenIo() {
  if (g_io_fd >= 0) g_real.close(g_io_fd);
  g_io_fd = open("/proc/self/io", O_RDONLY | O_CLOEXEC);
}

// Whether the calling thread may have written to a descriptor another program waits for since
// its last wait: this process's write count moved (any thread's write, writev, pwrite …, also
// those the C library makes itself), or it closed, shut down or sent (NoteTouched). When the
// count cannot be read: yes.
bool WroteSinceLastWait() {
  char buf[256];
  const ssize_t n = g_io_fd >= 0 ? pread(g_io_fd, buf, sizeof buf - 1, 0) : -1;
  if (n <= 0) return true;
  buf[n] = '\0';
  const char* field = std::strstr(buf, "syscw: ");
  if (!field) return true;
  const std::uint64_t syscw = std::strtoull(field + 7, nullptr, 10);
  const bool wrote = syscw != t_syscw || t_touched;
  t_syscw = syscw;
  t_touched = false;
  return wrote;
}

// Lookahead: the acknowledgement that makes the programs idle moves the clock itself
// (lockstep_advance.h); hil hears of it only when the next move lies beyond its horizon.
void MoveClockOrNotifyHil(const lk::ThreadSlot* self) {
  g_shared->host_wake.fetch_add(1);
  if (lk::MoveClock(*g_shared, self) != lk::MoveResult::kStalled) return;
  if (g_shared->hil_waiting.load() != 0) Futex(&g_shared->host_wake, FUTEX_WAKE, INT_MAX);
}

// While hil writes ahead, whether `self` is the only thread on the clock: no other thread's wait
// can concern what it wrote, and hil reads the links only at the drain's turn (which reads them
// in any case), so the write count (/proc/self/io, which the kernel formats as text at every
// read) is not asked. It is asked again, and taken as moved, once another thread joins.
bool AloneAndAhead(const lk::ThreadSlot* self) {
  if (g_shared->lookahead.load() == 0) return false;
  const int used = std::min(g_shared->slots_used.load(), lk::kMaxThreads);
  for (int i = 0; i < used; ++i) {
    if (&g_shared->slots[i] != self && g_shared->slots[i].tid.load() != 0) return false;
  }
  t_touched = true;
  return true;
}

// Tells hil that what it could read from the programs may have changed (lockstep_shared.h).
void NoteHostWrite() { g_shared->host_writes.fetch_add(1); }

// Asks the other waiting threads whose condition what this thread did may have met to look again:
// after a write (`wrote`: WroteSinceLastWait), those waiting for input on descriptors other than
// hil's links (a pipe another program writes) and those of its own process (they share its
// descriptors); in any case those waiting for room to write on such descriptors (a read makes
// room). A thread waiting only for hil's links or a deadline is left asleep: only hil changes
// what it waits for.
void AskOthersToLook(const lk::ThreadSlot* self, bool wrote) {
  const std::int32_t pid = self->pid.load();
  const int used = std::min(g_shared->slots_used.load(), lk::kMaxThreads);
  for (int i = 0; i < used; ++i) {
    lk::ThreadSlot& s = g_shared->slots[i];
    if (&s == self || s.tid.load() == 0 || s.state.load() != lk::kWaiting) continue;
    if (s.on_descriptors.load() == 0) continue;
    const std::uint64_t links = s.links.load();
    const bool concerned = (links & lk::kEveryGrant) != 0 ||
                           (wrote && ((links & lk::kOtherFd) != 0 || s.pid.load() == pid));
    if (!concerned) continue;
    s.seq.fetch_add(1);
    Futex(&s.seq, FUTEX_WAKE, INT_MAX);
  }
}

void FreeSlot(lk::ThreadSlot* s) {
  s->state.store(lk::kRunning);  // a slot claimed again starts running (lockstep_shared.h)
  s->tid.store(0);
}

// pthread key destructor: the thread ends, hil no longer waits for it.
void OnThreadExit(void* slot) {
  if (!g_shared || !slot) return;
  FreeSlot(static_cast<lk::ThreadSlot*>(slot));
  NoteHostWrite();
  NotifyHil();
}

lk::ThreadSlot* ClaimSlot() {
  const auto tid = static_cast<std::int32_t>(syscall(SYS_gettid));
  // a program exec'd by a preloaded one keeps its thread id: the slot is its own
  const int used = g_shared->slots_used.load();
  for (int i = 0; i < used && i < lk::kMaxThreads; ++i) {
    if (g_shared->slots[i].tid.load() == tid) return &g_shared->slots[i];
  }
  for (int i = 0; i < lk::kMaxThreads; ++i) {
    std::int32_t free = 0;
    lk::ThreadSlot& s = g_shared->slots[i];
    if (!s.tid.compare_exchange_strong(free, tid)) continue;
    s.pid.store(static_cast<std::int32_t>(getpid()));
    s.deadline_ns.store(lk::kNoDeadline);
    int hi = g_shared->slots_used.load();
    while (hi < i + 1 && !g_shared->slots_used.compare_exchange_weak(hi, i + 1)) {
    }
    return &s;
  }
  return nullptr;  // full: this thread blocks the real way
}

void RegisterProcess() {
  const auto pid = static_cast<std::int32_t>(getpid());
  for (int i = 0; i < lk::kMaxProcesses; ++i) {
    lk::ProcessEntry& p = g_shared->processes[i];
    std::int32_t free = 0;
    if (!p.pid.compare_exchange_strong(free, pid)) continue;
    std::memset(p.comm, 0, sizeof p.comm);
    const int fd = open("/proc/self/comm", O_RDONLY | O_CLOEXEC);
    if (fd >= 0) {
      const ssize_t n = g_real.read(fd, p.comm, sizeof p.comm - 1);
      if (n > 0 && p.comm[n - 1] == '\n') p.comm[n - 1] = '\0';
      close(fd);
    }
    int hi = g_shared->processes_used.load();
    while (hi < i + 1 && !g_shared->processes_used.compare_exchange_weak(hi, i + 1)) {
    }
    return;
  }
}

void AfterForkInChild() {
  t_slot = nullptr;  // a child counts from its own first wait
  t_touched = true;
  if (g_shared) OpenIo();  // its own write count
}

lk::ThreadSlot* Slot() {
  if (!SharedState()) return nullptr;
  if (!t_slot) {
    t_slot = ClaimSlot();
    if (t_slot) pthread_setspecific(g_slot_key, t_slot);
  }
  return t_slot;
}

__attribute__((constructor)) void Load() {
  ResolveAll();
  const char* path = std::getenv(lk::kEnvFile);
  if (!path || !*path) return;
  const int fd = open(path, O_RDWR | O_CLOEXEC);
  if (fd < 0) return;
  void* m = mmap(nullptr, sizeof(lk::Shared), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  close(fd);
  if (m == MAP_FAILED) return;
  auto* s = static_cast<lk::Shared*>(m);
  if (s->magic != lk::kMagic || s->version != lk::kVersion) {
    munmap(m, sizeof(lk::Shared));
    return;
  }
  if (pthread_key_create(&g_slot_key, OnThreadExit) != 0) return;
  pthread_atfork(nullptr, nullptr, AfterForkInChild);
  g_shared = s;
  OpenIo();
  // The main thread's slot (running) before the process is listed: hil starts its first turn
  // once the hosts are listed and waits for every claimed slot, so a process listed without a
  // slot would count as idle until the claim. Descheduled in between on a loaded machine, it
  // ran its start-up at a later emulated time than in another run.
  Slot();  // the main thread runs from now on: hil waits until it first waits
  RegisterProcess();
  NotifyHil();
}

__attribute__((destructor)) void Unload() {
  if (!g_shared) return;
  // exit(): this process's threads end with it
  const auto pid = static_cast<std::int32_t>(getpid());
  for (int i = 0; i < g_shared->slots_used.load() && i < lk::kMaxThreads; ++i) {
    if (g_shared->slots[i].pid.load() == pid && g_shared->slots[i].tid.load() != 0)
      FreeSlot(&g_shared->slots[i]);
  }
  NoteHostWrite();
  NotifyHil();
}

}  // namespace

void NoteTouched() { t_touched = true; }

void ForgetDescriptor(int fd) {
  if (fd >= 0 && fd == g_io_fd) g_io_fd = -1;
}

void ForgetDescriptors(unsigned first, unsigned last) {
  if (g_io_fd >= 0 && static_cast<unsigned>(g_io_fd) >= first &&
      static_cast<unsigned>(g_io_fd) <= last)
    g_io_fd = -1;
}

const RealFunctions& Real() {
  if (!g_resolved) ResolveAll();
  return g_real;
}

lk::Shared* SharedState() {
  return g_shared && g_shared->passthrough.load() == 0 ? g_shared : nullptr;
}

std::int64_t EmulatedNowNs() { return g_shared->now_ns.load(); }

bool Emulated(clockid_t clock) {
  if (!SharedState()) return false;
  switch (clock) {
    case CLOCK_REALTIME:
    case CLOCK_REALTIME_COARSE:
    case CLOCK_MONOTONIC:
    case CLOCK_MONOTONIC_COARSE:
    case CLOCK_MONOTONIC_RAW:
    case CLOCK_BOOTTIME:
      return true;
    default:
      return false;
  }
}

std::int64_t ClockReadingNs(clockid_t clock, std::int64_t t_ns) {
  if (clock == CLOCK_REALTIME || clock == CLOCK_REALTIME_COARSE)
    return g_shared->utc_epoch_ns + t_ns;
  return lk::kMonotonicBaseNs + t_ns;
}

std::int64_t EmulatedTimeOf(clockid_t clock, std::int64_t reading_ns) {
  return reading_ns - ClockReadingNs(clock, 0);
}

std::int64_t ToNs(const timespec& ts) {
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

timespec ToTimespec(std::int64_t ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ns / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(ns % 1'000'000'000);
  if (ts.tv_nsec < 0) {
    ts.tv_nsec += 1'000'000'000;
    --ts.tv_sec;
  }
  return ts;
}

std::uint64_t LinkBitOf(int fd) {
  const int k = LinkIndexOf(fd);
  return k < 0 ? lk::kOtherFd : std::uint64_t{1} << k;
}

int FeedOf(int fd) {
  if (!SharedState() || g_shared->lookahead.load() == 0) return -1;
  const std::uint64_t bit = LinkBitOf(fd);
  for (int k = 0; k < lk::kFeedLinks; ++k) {
    if (bit == std::uint64_t{1} << k) return k;
  }
  return -1;
}

std::uint64_t FeedAvailable(int k) { return lk::FeedAvailable(*g_shared, k); }

void FeedConsumed(int k, std::uint64_t n) { g_shared->feeds[k].consumed.fetch_add(n); }

void NoteEpoll() {
  if (g_shared && g_shared->epoll_seen.load() == 0) g_shared->epoll_seen.store(1);
}

long Wait(long (*ready)(void* arg), void* arg, std::int64_t deadline_ns,
          std::uint64_t (*links)(void* arg)) {
  lk::ThreadSlot* s = Slot();
  if (!s) return kUnmanaged;
  const int saved_errno = errno;
  const std::uint32_t c0 = s->seq.load();  // before the first look
  // met already: the call returns as the real one would, without a word to anyone
  if (const long r = ready ? ready(arg) : 0; r != 0) return r;
  if (deadline_ns != lk::kNoDeadline && g_shared->now_ns.load() >= deadline_ns) return kDeadline;
  // told to hil before this thread can count as idle
  const bool wrote = !AloneAndAhead(s) && WroteSinceLastWait();
  if (wrote) NoteHostWrite();
  const std::uint64_t mask = !ready ? 0 : links ? links(arg) : lk::kAnything;
  s->deadline_ns.store(deadline_ns);
  s->links.store(mask);
  s->on_descriptors.store(ready ? 1 : 0);
  s->state.store(lk::kWaiting);
  s->waits.fetch_add(1);
  // what this thread did before it waits may be what another waits for: those look again
  AskOthersToLook(s, wrote);
  // Only hil makes hil's links ready or moves time on, and only while every thread waits: for a
  // wait on links alone the first look stands until someone asks this thread to look again. Any
  // other descriptor may have been made ready by another program between that look and the
  // moment this thread said it waits (it asked no one to look again then): it looks once more.
  bool looked = (mask & (lk::kOtherFd | lk::kEveryGrant)) == 0;
  for (;;) {
    const std::uint32_t c = s->seq.load();
    const long r = looked && c == c0 ? 0 : ready ? ready(arg) : 0;
    looked = false;
    if (r != 0) {
      s->state.store(lk::kRunning);
      return r;
    }
    if (deadline_ns != lk::kNoDeadline && g_shared->now_ns.load() >= deadline_ns) {
      s->state.store(lk::kRunning);
      errno = saved_errno;
      return kDeadline;
    }
    if (g_shared->passthrough.load() != 0) {
      s->state.store(lk::kRunning);
      return kUnmanaged;  // hil paces the run the old way: the real call waits
    }
    s->acked.store(c);
    s->looks.fetch_add(1);
    if (g_shared->lookahead.load() != 0) {
      MoveClockOrNotifyHil(s);
      if (s->seq.load() != c) continue;  // it moved the clock to this thread's own wake-up
    } else {
      NotifyHilIfIdle();
    }
    if (Futex(&s->seq, FUTEX_WAIT, c) != 0 && errno == EINTR) {
      s->state.store(lk::kRunning);
      return kInterrupted;
    }
  }
}

}  // namespace hil::preload

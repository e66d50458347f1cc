#pragma once
// The preload library's state (libhil_lockstep.so; contract in README.md beside this file): the
// shared file mapped at load, the real functions behind the interposed ones, each thread's slot,
// and the one wait every interposed blocking call goes through. No allocation after load, no
// exception, no lock: the calls may run in any thread at any time.

#include <dirent.h>
#include <poll.h>
#include <stdio.h>
#include <time.h>

#include <cstdint>

#include <sys/epoll.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <sys/types.h>

#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::preload {

/// The libc functions the library stands in front of (dlsym(RTLD_NEXT)).
struct RealFunctions {
  int (*clock_gettime)(clockid_t, timespec*);
  int (*nanosleep)(const timespec*, timespec*);
  int (*clock_nanosleep)(clockid_t, int, const timespec*, timespec*);
  int (*usleep)(useconds_t);
  unsigned (*sleep)(unsigned);
  int (*poll)(pollfd*, nfds_t, int);
  int (*ppoll)(pollfd*, nfds_t, const timespec*, const sigset_t*);
  int (*select)(int, fd_set*, fd_set*, fd_set*, timeval*);
  int (*pselect)(int, fd_set*, fd_set*, fd_set*, const timespec*, const sigset_t*);
  int (*epoll_wait)(int, epoll_event*, int, int);
  int (*epoll_pwait)(int, epoll_event*, int, int, const sigset_t*);
  ssize_t (*read)(int, void*, size_t);
  int (*close)(int);
  int (*shutdown)(int, int);
  ssize_t (*send)(int, const void*, size_t, int);
  ssize_t (*sendto)(int, const void*, size_t, int, const sockaddr*, socklen_t);
  ssize_t (*sendmsg)(int, const msghdr*, int);
  int (*ioctl)(int, unsigned long, ...);
  // closes and replacements of descriptors (interposed_closes.cc)
  int (*dup2)(int, int);
  int (*dup3)(int, int, int);
  int (*close_range)(unsigned, unsigned, int);
  void (*closefrom)(int);
  int (*fclose)(FILE*);
  FILE* (*freopen)(const char*, const char*, FILE*);
  FILE* (*freopen64)(const char*, const char*, FILE*);
  int (*pclose)(FILE*);
  int (*fcloseall)();
  int (*closedir)(DIR*);
  int (*daemon)(int, int);
};

/// The real functions (resolved at load; a call before that resolves them first).
const RealFunctions& Real();

/// The shared state, or null when the program runs without hil's clock (no HIL_LOCKSTEP, or the
/// file could not be mapped: every call is then passed through).
harness::lockstep::Shared* SharedState();

/// Emulated nanoseconds since t = 0.
std::int64_t EmulatedNowNs();
/// Whether `clock` reads emulated time, and its reading for emulated time `t_ns`.
bool Emulated(clockid_t clock);
std::int64_t ClockReadingNs(clockid_t clock, std::int64_t t_ns);
/// The emulated time at which `clock` reads `reading_ns`.
std::int64_t EmulatedTimeOf(clockid_t clock, std::int64_t reading_ns);

std::int64_t ToNs(const timespec& ts);
timespec ToTimespec(std::int64_t ns);

/// What Wait returns besides a readiness check's own answer (> 0, or −1 with errno).
enum WaitEnd : long {
  kDeadline = 0,         ///< the deadline came
  kUnmanaged = -1000,    ///< no slot (no hil, or the slots are full): block the real way
  kInterrupted = -1001,  ///< a signal arrived (the caller returns EINTR)
};

/// Notes that the calling thread did something that may meet another program's wait and that
/// the kernel's write count (/proc/self/io `syscw`) does not show: a close, shutdown or send on a
/// socket (interposed_sends.cc).
void NoteTouched();
/// The program closes `fd`: if it is the library's own /proc/self/io, the library no longer uses
/// it (and takes every wait for one after a write from then on).
void ForgetDescriptor(int fd);
/// The same for the descriptors `first` to `last` (both included).
void ForgetDescriptors(unsigned first, unsigned last);

/// The bit of descriptor `fd` in a slot's `links` mask (lockstep_shared.h): its link's, or
/// kOtherFd for anything that is not one of hil's links (descriptor_cache.h: one fstat the first
/// time).
std::uint64_t LinkBitOf(int fd);

/// Lookahead (hil writes ahead, lockstep_advance.h): the feed of `fd`'s link, or -1 when hil
/// does not write ahead or `fd` is not a link with a feed (as LinkBitOf).
int FeedOf(int fd);
/// Bytes of feed `k` that have arrived by now and the programs have not read.
std::uint64_t FeedAvailable(int k);
/// The programs read `n` bytes of feed `k`.
void FeedConsumed(int k, std::uint64_t n);
/// A thread waits in epoll: hil stops writing ahead at its next look (the library cannot tell
/// which descriptors an epoll set holds).
void NoteEpoll();

/// Waits in emulated time until `ready(arg)` (a non-blocking look at descriptors: > 0 met, −1
/// failed with errno, 0 not yet; null: a sleep, never met) or until emulated time reaches
/// `deadline_ns` (kNoDeadline: none); see the protocol in lockstep_shared.h. `links(arg)` names
/// the links the descriptors are (LinkBitOf each; null: any, kAnything), asked once the wait
/// blocks. Returns ready's answer or a WaitEnd.
long Wait(long (*ready)(void* arg), void* arg, std::int64_t deadline_ns,
          std::uint64_t (*links)(void* arg) = nullptr);

}  // namespace hil::preload

// A test library preloaded after libhil_lockstep.so: the process's first syscall(SYS_gettid), the
// library's claim of the main thread's slot at load, is held back by HIL_TEST_START_DELAY_MS of
// wall time (default 300), as on a machine so loaded that the program is descheduled there. It
// delays nothing else and passes every call on to the C library's syscall().
#include <dlfcn.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cstdarg>
#include <cstdlib>

#include <sys/syscall.h>

namespace {

using SyscallFn = long (*)(long, ...);
std::atomic<bool> g_delayed{false};

SyscallFn RealSyscall() {
  static const auto real = reinterpret_cast<SyscallFn>(dlsym(RTLD_NEXT, "syscall"));
  return real;
}

void HoldBack() {
  const char* text = std::getenv("HIL_TEST_START_DELAY_MS");
  const long ms = text ? std::atol(text) : 300;
  timespec ts{ms / 1000, (ms % 1000) * 1'000'000};
  // the real clock (the library interposes nanosleep): the system call itself
  while (RealSyscall()(SYS_nanosleep, &ts, &ts) != 0) {
  }
}

}  // namespace

extern "C" long syscall(long number, ...) {
  va_list ap;
  va_start(ap, number);
  long a[6];
  for (long& x : a) x = va_arg(ap, long);
  va_end(ap);
  if (number == SYS_gettid && !g_delayed.exchange(true)) HoldBack();
  return RealSyscall()(number, a[0], a[1], a[2], a[3], a[4], a[5]);
}

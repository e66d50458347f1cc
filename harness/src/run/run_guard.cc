#include "hil/harness/run/run_guard.h"

#include <signal.h>

#include <csignal>

namespace hil::harness {
namespace {

volatile std::sig_atomic_t g_signal = 0;
constexpr int kCaught[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kIgnored[] = {SIGPIPE, SIGXFSZ};
struct sigaction g_old[sizeof kCaught / sizeof kCaught[0] + sizeof kIgnored / sizeof kIgnored[0]];

void OnSignal(int sig) { g_signal = sig; }

}  // namespace

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  std::size_t k = 0;
  struct sigaction sa {};
  sa.sa_handler = OnSignal;
  sigemptyset(&sa.sa_mask);
  for (int s : kCaught) sigaction(s, &sa, &g_old[k++]);
  struct sigaction ign {};
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  for (int s : kIgnored) sigaction(s, &ign, &g_old[k++]);
}

InterruptGuard::~InterruptGuard() {
  std::size_t k = 0;
  for (int s : kCaught) sigaction(s, &g_old[k++], nullptr);
  for (int s : kIgnored) sigaction(s, &g_old[k++], nullptr);
}

int InterruptGuard::received() { return g_signal; }

}  // namespace hil::harness

// SetProcessNice: the nice value of every thread of hil, inherited by the threads and processes
// started afterwards (the run's workers, the estimator, the controller); a refusal is reported.
// Each case runs in a child process (a death test), so the test binary keeps its own priority.
#include "hil/harness/run/run_priority.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

int NiceOf(id_t tid) { return getpriority(PRIO_PROCESS, tid); }

// Fails the child with a message on stderr (the death test shows it).
void Require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "failed: %s\n", what);
  std::exit(1);
}

void SetsEveryThreadAndIsInherited() {
  std::atomic<id_t> before_tid{0};
  std::atomic<bool> stop{false};
  std::thread before([&] {
    before_tid = static_cast<id_t>(gettid());
    while (!stop) std::this_thread::yield();
  });
  while (before_tid == 0) std::this_thread::yield();
  const RunPriority p = SetProcessNice(7);  // raising the value needs no privilege
  Require(p.requested == 7 && p.nice == 7 && p.refused.empty(), "nice 7 granted");
  Require(NiceOf(before_tid) == 7, "a thread made before has it");
  int after = 0;
  std::thread([&] { after = NiceOf(static_cast<id_t>(gettid())); }).join();
  Require(after == 7, "a thread made after inherits it");
  const pid_t child = fork();
  if (child == 0) _exit(NiceOf(0) == 7 ? 0 : 1);
  int status = 0;
  waitpid(child, &status, 0);
  Require(WIFEXITED(status) && WEXITSTATUS(status) == 0, "a process started after inherits it");
  stop = true;
  before.join();
  std::exit(0);
}

TEST(RunPriorityTest, SetsEveryThreadAndIsInherited) {
  EXPECT_EXIT(SetsEveryThreadAndIsInherited(), ::testing::ExitedWithCode(0), "");
}

void ZeroLeavesThePriorityAsItIs() {
  Require(setpriority(PRIO_PROCESS, 0, 3) == 0, "set 3 beforehand");
  const RunPriority p = SetProcessNice(0);
  Require(p.requested == 0 && p.nice == 3 && p.refused.empty(), "left at 3");
  std::exit(0);
}

TEST(RunPriorityTest, ZeroLeavesThePriorityAsItIs) {
  EXPECT_EXIT(ZeroLeavesThePriorityAsItIs(), ::testing::ExitedWithCode(0), "");
}

// Without CAP_SYS_NICE (root gives it up with its uid) and with RLIMIT_NICE 0, a nice value
// lower than the current one is refused.
void ARefusalIsReported() {
  if (geteuid() == 0) Require(setuid(65534) == 0, "drop root");
  const rlimit none{0, 0};
  Require(setrlimit(RLIMIT_NICE, &none) == 0, "RLIMIT_NICE 0");
  const int before = NiceOf(0);
  const RunPriority p = SetProcessNice(-10);
  Require(p.requested == -10 && !p.refused.empty(), "refused, with the reason");
  Require(p.nice == before, "the priority it had");
  std::exit(0);
}

TEST(RunPriorityTest, ARefusalIsReportedAndTheRunKeepsItsPriority) {
  EXPECT_EXIT(ARefusalIsReported(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace hil::harness

// GroupSleepProbe: whether every thread of a process group sleeps, as virtual mode's host turns
// ask it (virtual_gate.h).
#include "hil/harness/dut/process_group.h"

#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

[[noreturn]] void Spin() {
  volatile unsigned long n = 0;
  for (;;) n = n + 1;
}

// A child in its own process group that blocks reading `fd` (1: then forks a busy grandchild; 2:
// spins itself) once it has read one byte.
pid_t StartChild(int read_fd) {
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    char c = 0;
    if (read(read_fd, &c, 1) != 1) _exit(1);
    if (c == '1' && fork() == 0) {
      Spin();
    }
    if (c == '2') {
      Spin();
    }
    pause();
    _exit(0);
  }
  setpgid(pid, pid);
  return pid;
}

bool AsleepWithin(GroupSleepProbe& probe, int tries) {
  for (int i = 0; i < tries; ++i) {
    if (probe.AllAsleep()) return true;
    timespec ts{0, 1'000'000};
    nanosleep(&ts, nullptr);
  }
  return false;
}

void Stop(pid_t pgid) {
  kill(-pgid, SIGKILL);
  while (waitpid(-pgid, nullptr, 0) > 0) {
  }
}

TEST(GroupSleepProbeTest, SleepingGroupThenASpinningOne) {
  int p[2];
  ASSERT_EQ(pipe(p), 0);
  const pid_t child = StartChild(p[0]);
  GroupSleepProbe probe(child);
  EXPECT_TRUE(AsleepWithin(probe, 2000)) << "blocked in read()";
  ASSERT_EQ(write(p[1], "2", 1), 1);
  timespec ts{0, 20'000'000};
  nanosleep(&ts, nullptr);
  for (int i = 0; i < 50; ++i) EXPECT_FALSE(probe.AllAsleep());
  Stop(child);
  close(p[0]);
  close(p[1]);
}

TEST(GroupSleepProbeTest, SeesAChildForkedAfterTheFirstLook) {
  int p[2];
  ASSERT_EQ(pipe(p), 0);
  const pid_t child = StartChild(p[0]);
  GroupSleepProbe probe(child);
  ASSERT_TRUE(AsleepWithin(probe, 2000));
  ASSERT_EQ(write(p[1], "1", 1), 1);  // the child forks a busy grandchild, then sleeps again
  timespec ts{0, 50'000'000};
  nanosleep(&ts, nullptr);
  for (int i = 0; i < 50; ++i) EXPECT_FALSE(probe.AllAsleep());
  Stop(child);
  close(p[0]);
  close(p[1]);
}

TEST(GroupSleepProbeTest, NoGroupIsNotAsleep) {
  GroupSleepProbe probe(-1);
  EXPECT_FALSE(probe.AllAsleep());
}

}  // namespace
}  // namespace hil::harness

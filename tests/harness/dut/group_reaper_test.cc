// GroupReaper (issue 40.1): the process groups a run owns die when hil dies, however (here: a
// stand-in for hil killed with SIGKILL), and only those it did not release; the descriptor it
// keeps (the run folder's lock) stays held until the last of them is gone.
#include "hil/harness/dut/group_reaper.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/wait.h>

#include "hil/harness/dut/process_group.h"
#include "hil/harness/dut/shell_spawn.h"

namespace hil::harness {
namespace {

template <typename F>
bool WaitFor(F&& done, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

// A stand-in for hil: makes a reaper keeping `lock_fd`, spawns a group of two sleeps (the shell's
// child is a grandchild: no parent-death signal), tells its pgid on `report_fd`, releases the
// group when `release`, and is then killed with SIGKILL.
[[noreturn]] void StandIn(int report_fd, int lock_fd, bool release) {
  GroupReaper reaper(lock_fd);
  close(lock_fd);
  const pid_t group = SpawnShell("sleep 600 & sleep 600; wait", {0, -1, -1});
  reaper.Watch(group);
  while (LiveGroupMembers(group).size() < 3) usleep(1000);  // the shell and both sleeps
  if (release) reaper.Release(group);
  [[maybe_unused]] const ssize_t n = write(report_fd, &group, sizeof group);
  kill(getpid(), SIGKILL);
  _exit(1);
}

struct Outcome {
  pid_t group = -1;
  std::string lock_path;
};

Outcome RunStandIn(bool release) {
  Outcome o;
  o.lock_path = (std::filesystem::temp_directory_path() /
                 ("hil_reaper_" + std::to_string(getpid()) + ".lock"))
                    .string();
  const int lock_fd = open(o.lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  EXPECT_GE(lock_fd, 0);
  EXPECT_EQ(flock(lock_fd, LOCK_EX), 0);
  int p[2];
  EXPECT_EQ(pipe(p), 0);
  const pid_t stand_in = fork();
  if (stand_in == 0) {
    close(p[0]);
    StandIn(p[1], lock_fd, release);
  }
  close(p[1]);
  close(lock_fd);  // the stand-in (and its reaper) hold the lock now
  EXPECT_EQ(read(p[0], &o.group, sizeof o.group), static_cast<ssize_t>(sizeof o.group));
  close(p[0]);
  int status = 0;
  waitpid(stand_in, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  return o;
}

bool LockFree(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  const bool free = fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) == 0;
  if (fd >= 0) close(fd);
  return free;
}

TEST(GroupReaperTest, TheGroupsOfAKilledRunDieAndThenTheLockIsFree) {
  const Outcome o = RunStandIn(false);
  ASSERT_GT(o.group, 0);
  EXPECT_TRUE(WaitFor([&] { return LiveGroupMembers(o.group).empty(); }, 10))
      << LiveGroupMembers(o.group).size() << " processes of the group live on";
  EXPECT_TRUE(WaitFor([&] { return LockFree(o.lock_path); }, 10));
  std::remove(o.lock_path.c_str());
}

TEST(GroupReaperTest, AReleasedGroupIsLeftAlone) {
  const Outcome o = RunStandIn(true);
  ASSERT_GT(o.group, 0);
  EXPECT_TRUE(WaitFor([&] { return LockFree(o.lock_path); }, 10));  // the reaper has exited
  // the shell dies with the stand-in (parent-death signal, delivered asynchronously) once it has
  // started its two sleeps, which are not killed: the group settles at those two
  EXPECT_TRUE(WaitFor([&] { return LiveGroupMembers(o.group).size() == 2u; }, 10))
      << LiveGroupMembers(o.group).size() << " processes of the group live";
  kill(-o.group, SIGKILL);
  std::remove(o.lock_path.c_str());
}

}  // namespace
}  // namespace hil::harness

// SpawnShell: the host processes start as `/bin/sh -c LINE` in a process group, and the call
// returns only once the child runs the shell (not while it is still a copy of hil holding hil's
// descriptors, which the first host turn's look at the group's open files took for the host's).
#include "hil/harness/dut/shell_spawn.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

std::string Target(const fs::path& link) {
  std::error_code ec;
  const fs::path p = fs::read_symlink(link, ec);
  return ec ? "" : p.string();
}

// Whether process `pid` has a descriptor open on `path`.
bool HoldsFile(pid_t pid, const std::string& path) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    if (Target(e.path()) == path) return true;
  }
  return false;
}

void KillAndReap(pid_t pid) {
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
}

TEST(ShellSpawnTest, ReturnsOnceTheChildRunsTheShellWithoutTheParentsDescriptors) {
  const std::string held = (fs::temp_directory_path() / "hil_shell_spawn_held").string();
  const int fd = open(held.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  ASSERT_GE(fd, 0);
  const std::string self = Target("/proc/self/exe");
  // Twenty times: a check right after the call would often see the forked copy of this test
  // (this program, holding `held`) if the call returned before the exec.
  for (int k = 0; k < 20; ++k) {
    const pid_t pid = SpawnShell("sleep 30", {});
    ASSERT_GT(pid, 0);
    EXPECT_NE(Target("/proc/" + std::to_string(pid) + "/exe"), self) << "attempt " << k;
    EXPECT_FALSE(HoldsFile(pid, held)) << "attempt " << k;
    EXPECT_EQ(getpgid(pid), pid) << "a new group led by the child";
    KillAndReap(pid);
  }
  close(fd);
  fs::remove(held);
}

TEST(ShellSpawnTest, JoinsTheGivenGroupAndWritesWhereItIsTold) {
  int out[2];
  ASSERT_EQ(pipe2(out, O_CLOEXEC), 0);
  const pid_t leader = SpawnShell("sleep 30", {});
  const pid_t pid =
      SpawnShell("echo out; echo err >&2; read x; echo \"[$x]\"", {leader, out[1], out[1]});
  close(out[1]);
  EXPECT_EQ(getpgid(pid), leader);
  std::string text;
  char buf[64];
  ssize_t n;
  while ((n = read(out[0], buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
  close(out[0]);
  EXPECT_EQ(text, "out\nerr\n[]\n") << "stdout and stderr to the pipe, stdin from /dev/null";
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status));
  KillAndReap(leader);
}

}  // namespace
}  // namespace hil::harness

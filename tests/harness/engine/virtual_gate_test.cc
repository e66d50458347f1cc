// VirtualGate's first host turn (virtual_gate.h): it waits until the host holds its links and
// sleeps, and then knows whether the host holds any of them open for writing. A read-only host
// cannot write what a periodic turn waits for (Scheduler::HostTurn then does not wait).
#include "hil/harness/engine/virtual_gate.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

// A host in its own process group, as a run starts one (exec'd: it holds only what it opens):
// a shell that opens both links with `redirect` ("<" read-only, "<>" read-write), then sleeps.
pid_t StartHost(const fs::path& a, const fs::path& b, const std::string& redirect) {
  const std::string script =
      "exec 3" + redirect + a.string() + " 4" + redirect + b.string() + "; exec sleep 60";
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  return pid;
}

void Stop(pid_t pgid) {
  kill(-pgid, SIGKILL);
  while (waitpid(-pgid, nullptr, 0) > 0) {
  }
}

struct Links {
  fs::path dir;
  SerialEndpoint imu, gps;
  explicit Links(const std::string& tag)
      : dir(fs::temp_directory_path() / ("hil_vg_" + tag + std::to_string(getpid()))),
        imu("ttyI", Make(dir, "ttyI"), 115200, 1 << 16, (dir / "ttyI.cap").string()),
        gps("ttyG", Make(dir, "ttyG"), 115200, 1 << 16, (dir / "ttyG.cap").string()) {}
  ~Links() { fs::remove_all(dir); }
  static std::string Make(const fs::path& dir, const char* name) {
    fs::create_directories(dir);
    return (dir / name).string();
  }
};

// The gate after the host's first turn: HostReadsOnly().
bool ReadsOnlyAfterFirstTurn(Links& l, const std::string& redirect) {
  const pid_t host = StartHost(l.dir / "ttyI", l.dir / "ttyG", redirect);
  VirtualGate gate(
      {&l.imu, &l.gps}, 4096, [](std::size_t, bool) { return true; }, host);
  EXPECT_FALSE(gate.HostReadsOnly()) << "nothing is known before the first turn";
  EXPECT_TRUE(gate.WaitHostIdle());
  const bool reads_only = gate.HostReadsOnly();
  if (reads_only) {
    gate.NoteHostWrote();  // bytes came all the same: the turns wait again
    EXPECT_FALSE(gate.HostReadsOnly());
  }
  Stop(host);
  return reads_only;
}

TEST(VirtualGateTest, AHostHoldingItsLinksReadOnlyCannotWrite) {
  Links l("ro");
  EXPECT_TRUE(ReadsOnlyAfterFirstTurn(l, "<"));
}

TEST(VirtualGateTest, AHostHoldingALinkReadWriteMayWrite) {
  Links l("rw");
  EXPECT_FALSE(ReadsOnlyAfterFirstTurn(l, "<>"));
}

TEST(VirtualGateTest, WithoutAHostGroupEveryTurnWaits) {
  Links l("none");
  VirtualGate gate({&l.imu, &l.gps}, 4096, [](std::size_t, bool) { return true; });
  EXPECT_TRUE(gate.WaitHostIdle());
  EXPECT_FALSE(gate.HostReadsOnly());
}

// A link whose reader has gone (a closed loop's controller that ended) leaves the gate: bytes
// left unread on it no longer hold the other links back, and its own go without a wait.
TEST(VirtualGateTest, ALinkNoLongerReadHoldsNothingBack) {
  Links l("stop");
  int waits = 0;
  VirtualGate gate({&l.imu, &l.gps}, 4096, [&waits](std::size_t, bool) { return ++waits < 50; });
  // a host that has ttyG open and stops reading it (a port nobody has open drops its bytes)
  const int idle = open((l.dir / "ttyG").c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY);
  ASSERT_GE(idle, 0);
  SerialMessage m;
  m.t_ready = TimeFromSeconds(1.0);
  m.bytes = "$GPGGA,,,,,,0,,,,,,,,*66\r\n";
  ASSERT_TRUE(l.gps.Queue(m));
  ASSERT_TRUE(gate.BeforeWrite(l.gps, m.bytes.size(), m.t_ready, m.t_ready));
  l.gps.WriteChunks(1);
  const Time t_imu = TimeFromSeconds(1.01);
  EXPECT_FALSE(gate.BeforeWrite(l.imu, 25, t_imu, t_imu)) << "nobody reads ttyG: the IMU waits";
  EXPECT_GT(waits, 1);
  EXPECT_TRUE(gate.Reads(l.gps));
  gate.StopReading(l.gps);
  EXPECT_FALSE(gate.Reads(l.gps));
  EXPECT_TRUE(gate.Reads(l.imu));
  waits = 0;
  EXPECT_TRUE(gate.BeforeWrite(l.imu, 25, t_imu, t_imu));
  EXPECT_EQ(waits, 0) << "the unread GNSS bytes hold nothing back";
  EXPECT_TRUE(gate.BeforeWrite(l.gps, 10, t_imu, t_imu));
  EXPECT_EQ(waits, 0);
  close(idle);
}

// With a max_skew, a link refused by TryWrite is not asked about again for a short wall time
// (every event would otherwise cost a system call per link while the host is behind); after it,
// the host's progress is seen and the bytes go.
TEST(VirtualGateTest, ATryWriteRefusalIsNotAskedAgainAtOnce) {
  Links l("retry");
  VirtualGate gate(
      {&l.imu, &l.gps}, 1 << 16, [](std::size_t, bool) { return true; }, -1,
      std::chrono::milliseconds(10));
  SerialMessage m;
  m.t_ready = TimeFromSeconds(1.0);
  m.bytes = std::string(40, 'G');
  ASSERT_TRUE(l.gps.Queue(m));
  ASSERT_TRUE(gate.TryWrite(l.gps, m.bytes.size(), m.t_ready, m.t_ready));
  const int fd = open((l.dir / "ttyG").c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY);
  ASSERT_GE(fd, 0);
  l.gps.WriteChunks(1);
  // the IMU's bytes 0.5 s later: the GNSS bytes must be read first
  const Time t = TimeFromSeconds(1.5);
  const auto refused = std::chrono::steady_clock::now();
  EXPECT_FALSE(gate.TryWrite(l.imu, 25, t, t));
  char buf[64];
  ASSERT_EQ(read(fd, buf, sizeof buf), 40);
  const bool again = gate.TryWrite(l.imu, 25, t, t);
  const auto elapsed = std::chrono::steady_clock::now() - refused;
  if (elapsed < std::chrono::microseconds(45)) {
    EXPECT_FALSE(again) << "refused again without asking";
  } else {
    std::printf("the retry came %lld us after the refusal: not checked\n",
                static_cast<long long>(elapsed / std::chrono::microseconds(1)));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(again || gate.TryWrite(l.imu, 25, t, t)) << "the host's read is seen after it";
  close(fd);
}

}  // namespace
}  // namespace hil::harness

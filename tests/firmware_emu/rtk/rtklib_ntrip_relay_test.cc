// RTKLIB's str2str (Debian package rtklib) relays the emulated base's RTCM 3 stream through a real
// NTRIP caster on localhost: base stream → TCP → str2str (tcpsvr in, ntripc caster out, mount
// HIL) → str2str (NTRIP client in, file out). The relayed file must hold a whole copy of the
// stream, byte for byte, with no CRC error. The stream is fed again and again until a copy has gone
// through (the client may connect after the first bytes; it retries every 0.3 s, not str2str's
// default 10 s), within a bounded wait; both str2str processes are started here in their own
// process group and killed at the end. Skips without str2str.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>

#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include "rtk_base_fixture.h"

namespace hil::rtk {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

int FreePort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t len = sizeof a;
  getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  close(fd);
  return ntohs(a.sin_port);
}

pid_t Spawn(const std::string& command) {
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  return pid;
}

void Stop(pid_t pid) {
  kill(-pid, SIGINT);
  for (int i = 0; i < 50; ++i) {
    if (waitpid(pid, nullptr, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(-pid, SIGKILL);
  waitpid(pid, nullptr, 0);
}

int Connect(int port, Clock::time_point deadline) {
  while (Clock::now() < deadline) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return fd;
    close(fd);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return -1;
}

std::string Read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(RtklibNtripRelay, StreamCrossesStr2strCasterAndClientByteForByte) {
  if (std::system("command -v str2str >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "str2str is not installed (Debian package rtklib; see ci/setup)";
  signal(SIGPIPE, SIG_IGN);
  const fs::path dir = fs::temp_directory_path() / ("hil_ntrip_relay_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string stream = test::BaseStream(test::KarajBase(rtcm3::MsmKind::kMsm7), 30, 1);
  const int in_port = FreePort(), caster_port = FreePort();
  const fs::path relay = dir / "relay.rtcm3";
  const pid_t caster = Spawn("str2str -in tcpsvr://:" + std::to_string(in_port) +
                             " -out ntripc://:" + std::to_string(caster_port) + "/HIL > " +
                             (dir / "caster.log").string() + " 2>&1");
  const pid_t client = Spawn("str2str -in ntrip://localhost:" + std::to_string(caster_port) +
                             "/HIL -r 300 -out file://" + relay.string() + " > " +
                             (dir / "client.log").string() + " 2>&1");
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  const int fd = Connect(in_port, deadline);
  bool relayed = false;
  int copies = 0;
  while (fd >= 0 && !relayed && Clock::now() < deadline) {
    if (send(fd, stream.data(), stream.size(), 0) != static_cast<ssize_t>(stream.size())) break;
    ++copies;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    relayed = Read(relay).find(stream) != std::string::npos;
  }
  if (fd >= 0) close(fd);
  Stop(client);
  Stop(caster);
  ASSERT_GE(fd, 0) << "str2str's TCP server did not accept within 30 s";
  const std::string got = Read(relay);
  EXPECT_TRUE(relayed) << copies << " copies fed, " << got.size() << " bytes relayed";
  const rtcm3::SplitResult r = rtcm3::Split(got);
  EXPECT_EQ(r.crc_errors, 0U);
  EXPECT_GE(r.bodies.size(), 33U);  // at least one whole copy: 30 MSM7 + 3 × 1006
  RecordProperty("copies_fed", std::to_string(copies));
  RecordProperty("bytes_relayed", std::to_string(got.size()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::rtk

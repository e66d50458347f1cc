// Our candump log against can-utils on a real vcan0: canplayer replays a log we wrote, and a log
// candump -l wrote is read back by our reader, frame for frame.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sys/wait.h>

#include "hil/firmware_emu/link/candump_log.h"

#include "vcan_test_util.h"

namespace hil::link {
namespace {

namespace fs = std::filesystem;
using test::Iface;
using test::ReceiveFrames;

std::vector<CanWireFrame> Frames() {
  std::vector<CanWireFrame> out;
  for (const char* t :
       {"123#DEADBEEF", "09F80180#8868111FBFA49103", "09F80280#07FC5C3DFA00FFFF", "7FF#",
        "0CF02AE2#007D007D007D0005", "321#R", "1FFFFFFF#0102030405060708", "000#00"}) {
    out.push_back(*ParseCanFrameText(t));
  }
  return out;
}

fs::path TempDir() {
  const fs::path d = fs::temp_directory_path() / ("hil_interop_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

TEST(CandumpInteropVcanTest, CanplayerReplaysOurLog) {
  const fs::path log = TempDir() / "ours.log";
  const auto frames = Frames();
  {
    CandumpLogWriter w(log);
    std::int64_t t = 1370851200000000000LL;
    for (const auto& f : frames) {
      w.Write({UnixTimeFromNs(t), Iface(), f, 0});
      t += 20000000;  // 20 ms apart
    }
  }
  SocketCanPort rx(Iface());
  const std::string cmd = "canplayer -I " + log.string();
  const int status = std::system(cmd.c_str());
  ASSERT_EQ(status, 0) << cmd;
  const auto got = ReceiveFrames(rx, frames.size(), std::chrono::seconds(3));
  ASSERT_EQ(got.size(), frames.size()) << "canplayer did not play every line of our log";
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(got[i].frame, frames[i]) << FormatCanFrameText(frames[i]);
  // canplayer keeps the recorded gaps: 7 gaps of 20 ms
  const double span_ms =
      static_cast<double>(ToNs(got.back().t_kernel) - ToNs(got.front().t_kernel)) * 1e-6;
  EXPECT_GT(span_ms, 100.0);
  std::printf("canplayer played our %zu-frame log over %.1f ms (recorded 140 ms)\n", got.size(),
              span_ms);
}

TEST(CandumpInteropVcanTest, OurReaderReadsCandumpLogs) {
  // candump -l writes candump-<date>_<time>.log into its working directory
  const fs::path dir = TempDir() / "candump";
  fs::create_directories(dir);
  const auto frames = Frames();
  const pid_t logger = fork();
  ASSERT_GE(logger, 0);
  if (logger == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    execlp("candump", "candump", "-l", "-n", std::to_string(frames.size()).c_str(), Iface().c_str(),
           static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // candump binds its socket
  SocketCanPort tx(Iface());
  for (const auto& f : frames) ASSERT_TRUE(tx.Send(f).has_value());
  int status = 0;
  ASSERT_EQ(waitpid(logger, &status, 0), logger);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "candump -l failed";
  std::vector<fs::path> logs;
  for (const auto& e : fs::directory_iterator(dir)) logs.push_back(e.path());
  ASSERT_EQ(logs.size(), 1u);
  EXPECT_EQ(logs[0].filename().string().rfind("candump-", 0), 0u);
  const CandumpLog read = ReadCandumpLog(logs[0]);
  EXPECT_EQ(read.unreadable_lines, 0u);
  ASSERT_EQ(read.records.size(), frames.size());
  std::ifstream in(logs[0]);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(read.records[i].frame, frames[i]);
    EXPECT_EQ(read.records[i].iface, Iface());
    // and our writer reproduces candump's line exactly
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(FormatCandumpLine(read.records[i]), line);
    if (i == 0) std::printf("candump -l wrote: %s\n", line.c_str());
  }
}

}  // namespace
}  // namespace hil::link

// navd --replay of a candump log of the MCU's J1939 IMU frames (vectors/can/mcu_j1939.candump, the
// emulator's frames at their emulated times): the frames go through the decoder navd's online CAN
// input uses, the report counts them, and bad logs exit 2 naming the file and line.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_runner.h"

namespace hil::test {
namespace {

std::string GoldenCandump() { return SourceDir() + "/vectors/can/mcu_j1939.candump"; }

TEST(CandumpReplay, GoldenJ1939LogThroughTheOnlineDecoderPath) {
  TempDir dir("candump_replay");
  const CommandResult r =
      RunCommand(BinDir() + "/navd --replay " + GoldenCandump() + " --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // 69 frames: 30 ARI + 30 ACCS + 6 SSI2 + 3 pulses at 10 Hz; the samples before the first pulse
  // have no GPS time (the decoder's own unit test: vectors/can/mcu_j1939.expected.csv)
  EXPECT_NE(r.out.find("CAN frames 69 (remote 0, other interface 0): ari 30 accs 30 ssi2 6 pulses 3"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("unpaired 0 other_source 0 unknown_pgn 0 not_extended 0 bad_length 0"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("IMU samples: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("10.00 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mode ekf"), std::string::npos) << r.out;
}

TEST(CandumpReplay, ForeignFramesAreCountedAndBadLinesExitTwo) {
  TempDir dir("candump_replay_bad");
  const std::string golden = ReadFile(GoldenCandump());
  // a frame of another PGN and a remote frame: valid lines, counted, survived
  const std::string extra = dir.str() + "/extra.log";
  WriteFile(extra, golden + "(1370851210.000000) vcan0 18FEF100#0011223344556677\n" +
                       "(1370851210.100000) vcan0 0CF02AE2#R\n");
  const CommandResult ok =
      RunCommand(BinDir() + "/navd --replay " + extra + " --out " + dir.str() + "/o1");
  ASSERT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_NE(ok.out.find("CAN frames 71 (remote 1,"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("unknown_pgn 1 "), std::string::npos) << ok.out;
  const std::string bad = dir.str() + "/bad.candump";
  WriteFile(bad, "(1370851200.311015) vcan0 0CF02AE2#1F7D5480B27DC002\n(13708512 vcan0 1#\n");
  const CommandResult b =
      RunCommand(BinDir() + "/navd --replay " + bad + " --out " + dir.str() + "/o2");
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.out.find(bad + ":2: timestamp"), std::string::npos) << b.out;
  const std::string fd = dir.str() + "/fd.candump";
  WriteFile(fd, "(1370851200.311015) vcan0 0CF02AE2##10011223344556677\n");
  const CommandResult f =
      RunCommand(BinDir() + "/navd --replay " + fd + " --out " + dir.str() + "/o3");
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.out.find(fd + ":1: frame: CAN FD frame"), std::string::npos) << f.out;
  // a raw receiver log has no receive times: it cannot be merged with the candump's
  const std::string raw = dir.str() + "/raw.nmea";
  WriteFile(raw, "$GPGGA,080001.00,3528.7766,N,05035.8786,E,1,08,1.0,1312.0,M,0.0,M,,*4B\n");
  const CommandResult m = RunCommand(BinDir() + "/navd --replay " + raw + " " + GoldenCandump() +
                                     " --out " + dir.str() + "/o4");
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_NE(m.out.find(raw + ": a raw log has no recorded receive times"), std::string::npos)
      << m.out;
}

}  // namespace
}  // namespace hil::test

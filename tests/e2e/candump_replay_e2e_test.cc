// navd --replay of a candump log of the MCU's J1939 IMU frames (vectors/can/mcu_j1939.candump, the
// emulator's frames at their emulated times): the frames go through the decoder navd's online CAN
// input uses, the report counts them, and bad logs exit 2 naming the file and line.
#include <cstdio>
#include <fstream>
#include <sstream>
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
  EXPECT_NE(
      r.out.find("CAN frames 69 (remote 0, other interface 0): ari 30 accs 30 ssi2 6 pulses 3"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("unpaired 0 other_source 0 unknown_pgn 0 not_extended 0 bad_length 0"),
            std::string::npos)
      << r.out;
  // every sample the decoder gives reaches the filter: 12 after the pulses fix the GPS time
  EXPECT_NE(r.out.find("imu 12 no_time 17 gaps 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("IMU samples: 12 over 1.1 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mcu_ppm 38.0"), std::string::npos) << r.out;  // the vector's 37.5 ppm
  EXPECT_NE(r.out.find("10.00 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mode ekf"), std::string::npos) << r.out;
}

constexpr long long kStartUnix_ns = 1370851200000000000LL;  // 2013-06-10T08:00:00Z, the vector's

// "$BODY*CS\r\n" as lower-case hex
std::string NmeaHex(const std::string& body) {
  unsigned cs = 0;
  for (char c : body) cs ^= static_cast<unsigned char>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", cs);
  const std::string s = "$" + body + tail;
  std::string hex;
  for (unsigned char c : s) {
    char b[3];
    std::snprintf(b, sizeof b, "%02x", c);
    hex += b;
  }
  return hex;
}

// a GNSS capture of the vector's seconds: RMC + GGA at 1 Hz from 1 s, 3 mm/s north
std::string GnssCapture() {
  std::string cap = "# hil capture v2\n# link ttyGPS serial 9600\n# start_unix_ns " +
                    std::to_string(kStartUnix_ns) + "\n";
  for (int k = 1; k <= 7; ++k) {
    char hms[16], lat[16];
    std::snprintf(hms, sizeof hms, "0800%02d.00", k);
    std::snprintf(lat, sizeof lat, "3528.%05d", 77658 + 2 * k);
    const long long t = k * 1000000000LL + 100000000LL;
    cap += "tx " + std::to_string(t) + " 1042 0 NMEA-RMC " +
           NmeaHex(std::string("GPRMC,") + hms + ",A," + lat +
                   ",N,05035.87859,E,0.9,30.0,100613,,,A") +
           "\n";
    cap += "tx " + std::to_string(t + 80000000) + " 1042 0 NMEA-GGA " +
           NmeaHex(std::string("GPGGA,") + hms + "," + lat +
                   ",N,05035.87859,E,1,08,1.0,1312.0,M,0.0,M,,") +
           "\n";
  }
  return cap;
}

// the candump log as a run's CAN capture (captures/vcan0.cap): ftx frames at emulated times
std::string CanCapture(const std::string& candump) {
  std::string cap = "# hil capture v2\n# link vcan0 can vcan0\n# start_unix_ns " +
                    std::to_string(kStartUnix_ns) + "\n";
  std::istringstream in(candump);
  for (std::string line; std::getline(in, line);) {
    long long s = 0, us = 0;
    char frame[64];
    if (std::sscanf(line.c_str(), "(%lld.%lld) vcan0 %63s", &s, &us, frame) != 3) continue;
    cap += "ftx " + std::to_string(s * 1000000000LL + us * 1000LL - kStartUnix_ns) + " 0 0 J1939 " +
           frame + "\n";
  }
  return cap;
}

// GNSS capture + candump merged on Unix time; the same frames as a CAN capture give the same
// report and the same solution files (the one decoder path)
TEST(CandumpReplay, MergesWithACaptureAndMatchesTheCanCapturePath) {
  TempDir dir("candump_replay_merge");
  const std::string gps = dir.str() + "/ttyGPS.cap", can = dir.str() + "/vcan0.cap";
  WriteFile(gps, GnssCapture());
  WriteFile(can, CanCapture(ReadFile(GoldenCandump())));
  const CommandResult a = RunCommand(BinDir() + "/navd --replay " + gps + " " + GoldenCandump() +
                                     " --out " + dir.str() + "/a");
  const CommandResult b =
      RunCommand(BinDir() + "/navd --replay " + gps + " " + can + " --out " + dir.str() + "/b");
  ASSERT_EQ(a.exit_code, 0) << a.out;
  ASSERT_EQ(b.exit_code, 0) << b.out;
  EXPECT_NE(a.out.find("GNSS fixes: 7 over 6.0 s, 1.00 Hz"), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("CAN frames 69 "), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("late fixes 0"), std::string::npos) << a.out;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(ReadFile(dir.str() + "/a/KF_GINS_Navresult.nav"),
            ReadFile(dir.str() + "/b/KF_GINS_Navresult.nav"));
  // a run's serial capture has no start time: the CAN capture beside it has it (as in a run)
  std::string gps_nostart = GnssCapture();
  gps_nostart.erase(gps_nostart.find("# start_unix_ns"), 36);
  WriteFile(dir.str() + "/ttyGPS_nostart.cap", gps_nostart);
  const CommandResult d =
      RunCommand(BinDir() + "/navd --replay " + dir.str() + "/ttyGPS_nostart.cap " +
                 GoldenCandump() + " --out " + dir.str() + "/d");
  ASSERT_EQ(d.exit_code, 0) << d.out;
  EXPECT_EQ(d.out, a.out);
  // without any capture that knows the start, it cannot go on the candump's Unix time
  TempDir alone("candump_replay_alone");
  const std::string nostart = alone.str() + "/nostart.cap";
  WriteFile(nostart, gps_nostart);
  const CommandResult c = RunCommand(BinDir() + "/navd --replay " + nostart + " " +
                                     GoldenCandump() + " --out " + alone.str() + "/c");
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_NE(c.out.find(nostart + ": no '# start_unix_ns' header"), std::string::npos) << c.out;
}

TEST(CandumpReplay, ForeignFramesAreCountedAndBadLinesExitTwo) {
  TempDir dir("candump_replay_bad");
  const std::string golden = ReadFile(GoldenCandump());
  // a frame of another source, one of another PGN and a remote frame: valid lines, counted,
  // survived
  const std::string extra = dir.str() + "/extra.log";
  WriteFile(extra, golden + "(1370851210.000000) vcan0 18FEF100#0011223344556677\n" +
                       "(1370851210.050000) vcan0 18FEF1E2#0011223344556677\n" +
                       "(1370851210.100000) vcan0 0CF02AE2#R\n");
  const CommandResult ok =
      RunCommand(BinDir() + "/navd --replay " + extra + " --out " + dir.str() + "/o1");
  ASSERT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_NE(ok.out.find("CAN frames 72 (remote 1,"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("other_source 1 unknown_pgn 1 "), std::string::npos) << ok.out;
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

// Golden vectors of the WT901C emulator (vectors/wt901c): the byte stream of a session (5 s,
// default 10 Hz at 9600 baud, a yaw wrap through ±180°, then unlock, rate change, save, register
// reads, an automatic rate reduction and a yaw zeroing) and, per packet, the continuous values a
// decoder must read back within one LSB. Re-created byte for byte from a fixed seed;
// HIL_REGEN_VECTORS=1 rewrites them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/attitude/wit_packet.h"
#include "hil/firmware_emu/attitude/wt901c_device.h"

#include "wit_truth.h"

namespace hil::wit {
namespace {

constexpr std::uint64_t kSeed = 20190614;

std::vector<test::HostCommand> SessionCommands() {
  auto at = [](double s, std::string b) { return test::HostCommand{TimeFromSeconds(s), b}; };
  return {
      at(3.000, EncodeWriteCommand(0x69, 0xB588)),  // unlock
      at(3.020, EncodeWriteCommand(0x03, 0x0007)),  // RRATE 20 Hz
      at(3.040, EncodeWriteCommand(0x00, 0x0000)),  // save
      at(3.120, EncodeWriteCommand(0x27, 0x0002)),  // read RSW, RRATE, BAUD, AXOFFSET
      at(4.000, EncodeWriteCommand(0x69, 0xB588)),
      at(4.020, EncodeWriteCommand(0x03, 0x0008)),  // 50 Hz: more than 9600 baud carries
      at(4.500, EncodeWriteCommand(0x01, 0x0004)),  // CALSW: set the Z angle to zero
      at(4.800, EncodeWriteCommand(0x27, 0x003D)),  // read roll, pitch, yaw, temperature
  };
}

double Wrap180(double a) { return a - 360.0 * std::floor((a + 180.0) / 360.0); }
std::string G(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", v + 0.0);
  return buf;
}

std::string ExpectedRow(const test::Sent& s) {
  const auto type = static_cast<unsigned char>(s.msg.bytes[1]);
  std::ostringstream r;
  r << ToNs(s.msg.t_ready) << ",0x" << std::hex << int{type} << std::dec;
  const Wt901cCycle& c = s.cycle;
  auto v3 = [&](const Eigen::Vector3d& v) {
    r << "," << G(v[0]) << "," << G(v[1]) << "," << G(v[2]);
  };
  const auto d3 = [&] {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(s.msg.bytes[8]) |
                                      (static_cast<unsigned char>(s.msg.bytes[9]) << 8));
  };
  switch (type) {
    case 0x51:
      v3(c.accel_g), r << "," << 25.0;
      break;
    case 0x52:
      v3(c.rate_dps), r << "," << 25.0;
      break;
    case 0x53:
      v3(Eigen::Vector3d(Wrap180(c.angle_deg[0]), Wrap180(c.angle_deg[1]),
                         Wrap180(c.angle_deg[2])));
      r << "," << d3();
      break;
    case 0x54:
      v3(c.mag_counts), r << "," << 25.0;
      break;
    default:  // 0x5F: the four registers, as unsigned values
      for (int k = 0; k < 4; ++k) {
        r << ","
          << (static_cast<unsigned char>(s.msg.bytes[2 + 2 * k]) |
              (static_cast<unsigned char>(s.msg.bytes[3 + 2 * k]) << 8));
      }
  }
  return r.str();
}

std::string ReadFile(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(Wt901cGoldenTest, SessionVectorIsReproducedByteForByte) {
  Wt901cDevice dev(Wt901cConfig{}, kSeed);
  auto sent = test::Run(dev, test::TurnTruth{}, TimeFromSeconds(5.0), SessionCommands());
  std::stable_sort(sent.begin(), sent.end(),
                   [](const auto& a, const auto& b) { return a.msg.t_ready < b.msg.t_ready; });
  std::string bin;
  std::ostringstream csv;
  csv << "# WT901C session: expected continuous values per packet (decode within one LSB).\n"
      << "# Generator: tests/firmware_emu/attitude/wt901c_golden_test.cc (HIL_REGEN_VECTORS=1 "
         "rewrites); seed "
      << kSeed << "; see vectors/wt901c/README.md\n"
      << "t_ready_ns,type,v0,v1,v2,v3\n";
  for (const auto& s : sent) {
    bin += s.msg.bytes;
    csv << ExpectedRow(s) << "\n";
  }
  EXPECT_EQ(dev.stats().read_replies, 2u);
  EXPECT_EQ(dev.stats().saves, 1u);
  const std::string dir = HIL_TEST_SOURCE_DIR "/vectors/wt901c/";
  if (const char* regen = std::getenv("HIL_REGEN_VECTORS"); regen && std::string(regen) == "1") {
    std::ofstream(dir + "wt901c_session.bin", std::ios::binary) << bin;
    std::ofstream(dir + "wt901c_session.expected.csv") << csv.str();
  }
  EXPECT_EQ(ReadFile(dir + "wt901c_session.bin"), bin) << "HIL_REGEN_VECTORS=1 rewrites";
  EXPECT_EQ(ReadFile(dir + "wt901c_session.expected.csv"), csv.str());
}

}  // namespace
}  // namespace hil::wit

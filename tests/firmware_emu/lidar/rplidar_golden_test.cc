// Golden vectors of the RPLIDAR emulator (vectors/rplidar): the byte stream of a 1.2 s session
// (health, info, sample rate, a standard scan, stop, an express scan, a bad request, reset) of an
// A1M8 on a vehicle driving along aisle 0, and per sample what a decoder must read back.
// Re-created byte for byte from a fixed seed; HIL_REGEN_VECTORS=1 rewrites them.
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/lidar/rplidar_device.h"

#include "aisle_truth.h"
#include "golden_file.h"

namespace hil::lidar {
namespace {

constexpr std::uint64_t kSeed = 20200502;

std::vector<test::HostCommand> SessionCommands() {
  auto at = [](double s, std::string b) { return test::HostCommand{TimeFromSeconds(s), b}; };
  return {
      at(0.000, EncodeRequest(0x52)),                        // GET_HEALTH
      at(0.010, EncodeRequest(0x50)),                        // GET_INFO
      at(0.020, EncodeRequest(0x59)),                        // GET_SAMPLERATE
      at(0.030, EncodeRequest(0xFF, std::string(4, '\0'))),  // GET_ACC_BOARD_FLAG
      at(0.040, EncodeRequest(0x20)),                        // SCAN: nodes from 0.5 s (motor)
      at(0.700, EncodeRequest(0x25)),                        // STOP
      at(0.750, EncodeRequest(0x82, std::string(5, '\0'))),  // EXPRESS_SCAN, legacy
      at(1.000, std::string("\xA5\x82\x05\x00\x00\x00\x00\x00\x00", 9)),  // bad checksum
      at(1.100, EncodeRequest(0x40)),                                     // RESET → banner
  };
}

TEST(RplidarGolden, SessionBytesAndExpectations) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  RplidarConfig c;
  c.mount = {0.1, 0, 0.2, 0};  // below the ridge tops: it sees the ridge sides, posts and walls
  RplidarDevice dev(c, w, kSeed);
  std::ostringstream csv;
  csv << "t_ns,kind,angle_deg,true_range_m,measured_m,quality,start\n";
  std::string bin;
  test::RunDevice(dev, test::AisleTruth{}, TimeFromSeconds(1.2), SessionCommands(),
                  [&](const SerialMessage& m, bool data) {
                    bin += m.bytes;
                    if (!data) {
                      csv << ToNs(m.t_ready) << ",response," << m.name << ",,,,\n";
                      return;
                    }
                    const char* kind = m.name == "RPLIDAR-CAPSULE" ? "capsule" : "node";
                    for (const LidarSample& s : dev.last_samples()) {
                      char row[160];
                      std::snprintf(row, sizeof row, "%lld,%s,%.6f,%.6f,%.6f,%u,%d\n",
                                    static_cast<long long>(ToNs(s.t)), kind, s.angle_deg,
                                    s.true_range_m, s.measured_m, unsigned{s.quality},
                                    s.start ? 1 : 0);
                      csv << row;
                    }
                  });
  EXPECT_EQ(dev.request_stats().bad_checksum, 1u);
  EXPECT_EQ(dev.stats().resets, 1u);
  EXPECT_GT(dev.stats().capsules, 20u);
  test::CheckOrWriteGolden("vectors/rplidar/rplidar_session.bin", bin);
  test::CheckOrWriteGolden("vectors/rplidar/rplidar_session.expected.csv", csv.str());
}

}  // namespace
}  // namespace hil::lidar

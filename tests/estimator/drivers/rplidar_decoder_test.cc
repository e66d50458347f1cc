// The estimator's RPLIDAR decoder against the emulator's golden session (vectors/rplidar): every
// standard node and every express sample read back (angle within its quantisation, distance
// within half its resolution), the single responses, the banner skipped as garbage; corrupted
// nodes and capsules counted and survived.
#include "hil/estimator/drivers/rplidar_decoder.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

std::string SourcePath(const std::string& rel) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/" + rel;
}

struct Row {
  std::string kind;
  double angle_deg = 0, measured_m = 0;
  unsigned quality = 0;
  bool start = false;
};

std::vector<Row> ReadSamples() {
  std::ifstream in(SourcePath("vectors/rplidar/rplidar_session.expected.csv"));
  std::vector<Row> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    if (f.at(1) == "response") continue;
    rows.push_back({f[1], std::stod(f[2]), std::stod(f[4]), static_cast<unsigned>(std::stoul(f[5])),
                    f[6] == "1"});
  }
  return rows;
}

double AngleDiff(double a, double b) {
  const double d = std::fmod(a - b + 540.0, 360.0) - 180.0;
  return std::abs(d);
}

std::string ReadBin() {
  std::ifstream in(SourcePath("vectors/rplidar/rplidar_session.bin"), std::ios::binary);
  return {(std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()};
}

TEST(RplidarDecoder, ReadsTheGoldenSessionBack) {
  const std::string bytes = ReadBin();
  ASSERT_FALSE(bytes.empty());
  const std::vector<Row> rows = ReadSamples();
  std::vector<LidarPoint> points;
  std::vector<LidarSingleResponse> singles;
  RplidarDecoder dec([&](const LidarPoint& p) { points.push_back(p); },
                     [&](const LidarSingleResponse& r) { singles.push_back(r); });
  std::size_t chunk = 1;
  for (std::size_t i = 0; i < bytes.size(); i += chunk, chunk = chunk % 97 + 1)
    dec.Feed(std::string_view(bytes).substr(i, chunk));
  ASSERT_EQ(singles.size(), 4u);
  EXPECT_EQ(singles[0].type, 0x06);
  EXPECT_EQ(singles[0].health_status, 0);
  EXPECT_EQ(singles[1].info.model, 0x18);
  EXPECT_EQ(singles[1].info.firmware_major, 1);
  EXPECT_EQ(singles[1].info.firmware_minor, 29);
  EXPECT_EQ(singles[2].standard_us, 500);
  EXPECT_EQ(singles[2].express_us, 250);
  EXPECT_EQ(singles[3].acc_board_flag, 0u);
  // every node; every capsule's samples but the last capsule's (no next start angle: the host
  // stops before it)
  std::size_t nodes = 0, express = 0;
  for (const Row& r : rows) (r.kind == "node" ? nodes : express)++;
  ASSERT_EQ(points.size(), nodes + express - 32);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const LidarPoint& p = points[k];
    const Row& e = rows[k];
    ASSERT_EQ(p.express, e.kind == "capsule") << k;
    EXPECT_LE(AngleDiff(p.angle_deg, e.angle_deg), p.express ? 1.0 / 64 : 0.5 / 64) << k;
    EXPECT_NEAR(p.distance_m, e.measured_m, p.express ? 0.0005 + 1e-9 : 0.000125 + 1e-9) << k;
    if (!p.express) {
      EXPECT_EQ(p.quality, e.quality) << k;
      EXPECT_EQ(p.start, e.start) << k;
    }
  }
  EXPECT_EQ(dec.stats().descriptors, 6u);
  EXPECT_EQ(dec.stats().bad_nodes + dec.stats().bad_capsules, 0u);
  EXPECT_EQ(dec.stats().garbage_bytes, 64u);  // the banner after RESET
}

TEST(RplidarDecoder, SurvivesCorruptNodesAndCapsules) {
  std::string bytes = ReadBin();
  // flip bytes inside the node stream and inside a capsule
  const std::size_t first_node = 7 + 3 + 7 + 20 + 7 + 4 + 7 + 4 + 7;
  bytes[first_node + 101] = static_cast<char>(bytes[first_node + 101] ^ 0x01);  // a C bit
  const std::size_t express = bytes.find(std::string("\xA5\x5A\x54\x00\x00\x40\x82", 7));
  ASSERT_NE(express, std::string::npos);
  bytes[express + 7 + 84 * 3 + 40] ^= 0x10;  // capsule 3's checksum fails
  std::size_t n = 0;
  RplidarDecoder dec([&](const LidarPoint&) { ++n; });
  dec.Feed(bytes);
  EXPECT_GT(dec.stats().bad_nodes, 0u);
  EXPECT_GT(dec.stats().bad_capsules, 0u);
  EXPECT_GT(dec.stats().nodes, 390u);  // the stream resynchronised
  EXPECT_GT(dec.stats().capsules, 30u);
}

}  // namespace
}  // namespace hil::estimator::drivers

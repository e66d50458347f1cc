// The estimator's WT901C decoder against the emulator's golden session (vectors/wt901c): every
// packet read back within one LSB of the continuous value the emulator encoded; garbage and bad
// checksums counted and survived; the reference sheet's hand-computed example.
#include "hil/estimator/drivers/wt901c_decoder.h"

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

std::vector<WitPacket> Decode(const std::string& bytes, std::size_t chunk, WitDecoderStats* st) {
  std::vector<WitPacket> got;
  Wt901cDecoder dec([&](const WitPacket& p) { got.push_back(p); });
  for (std::size_t i = 0; i < bytes.size();) {
    dec.Feed(std::string_view(bytes).substr(i, chunk));
    i += chunk;
    chunk = chunk % 13 + 1;  // vary the piece sizes 1..13
  }
  if (st) *st = dec.stats();
  return got;
}

struct Row {
  unsigned type;
  double v[4];
};

std::vector<Row> ReadExpected() {
  std::ifstream in(SourcePath("vectors/wt901c/wt901c_session.expected.csv"));
  std::vector<Row> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::stringstream ss(line);
    std::string cell;
    std::getline(ss, cell, ',');  // t_ready_ns
    std::getline(ss, cell, ',');
    Row r{static_cast<unsigned>(std::stoul(cell, nullptr, 16)), {}};
    for (double& v : r.v) {
      std::getline(ss, cell, ',');
      v = std::stod(cell);
    }
    rows.push_back(r);
  }
  return rows;
}

std::string ReadBin() {
  std::ifstream f(SourcePath("vectors/wt901c/wt901c_session.bin"), std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

double AngleDiff(double a, double b) { return std::remainder(a - b, 360.0); }

TEST(Wt901cDecoderTest, ReferenceSheetExample) {
  WitDecoderStats st;
  const auto p = Decode(std::string("\x55\x53\x00\x00\x00\x00\x00\x40\x00\x00\xE8", 11), 11, &st);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].angle_deg.z(), 90.0);
  EXPECT_EQ(st.angle, 1u);
}

TEST(Wt901cDecoderTest, GoldenSessionReadsBackWithinOneLsb) {
  const std::string bin = ReadBin();
  const auto rows = ReadExpected();
  ASSERT_EQ(rows.size(), 282u);
  ASSERT_EQ(bin.size(), rows.size() * 11);
  WitDecoderStats st;
  const auto got = Decode(bin, 1, &st);
  ASSERT_EQ(got.size(), rows.size());
  EXPECT_EQ(st.bad_checksum, 0u);
  EXPECT_EQ(st.garbage_bytes, 0u);
  EXPECT_EQ(st.register_reads, 2u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("packet " + std::to_string(i));
    const WitPacket& p = got[i];
    const Row& r = rows[i];
    ASSERT_EQ(p.type, r.type);
    switch (p.type) {
      case 0x51:
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.accel_g[k], r.v[k], 16.0 / 32768);
        EXPECT_DOUBLE_EQ(p.temperature_c, r.v[3]);
        break;
      case 0x52:
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.rate_dps[k], r.v[k], 2000.0 / 32768);
        break;
      case 0x53:
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(AngleDiff(p.angle_deg[k], r.v[k]), 0.0, 180.0 / 32768);
          EXPECT_GE(p.angle_deg[k], -180.0);
          EXPECT_LT(p.angle_deg[k], 180.0);
        }
        EXPECT_EQ(p.version, r.v[3]);
        break;
      case 0x54:
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.mag_counts[k], r.v[k], 1.0);
        break;
      default:
        ASSERT_EQ(p.type, 0x5F);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(p.registers[k], r.v[k]);
    }
  }
}

TEST(Wt901cDecoderTest, GarbageAndBadChecksumsAreCountedAndSurvived) {
  std::string bin = ReadBin();
  ASSERT_GE(bin.size(), 440u);
  bin[11 * 3 + 5] ^= 0x10;                               // packet 3: bad sum
  bin[11 * 7 + 10] ^= 0x01;                              // packet 7: the sum byte itself
  bin.insert(11 * 20, "\x55\x55\xAA garbage \x55", 13);  // between packets 19 and 20
  bin.insert(0, "\x00\xFF\x55\x10", 4);
  WitDecoderStats st;
  const auto got = Decode(bin, 5, &st);
  EXPECT_EQ(got.size(), ReadExpected().size() - 2);
  EXPECT_GE(st.bad_checksum, 2u);  // the two damaged packets, plus false headers in the garbage
  EXPECT_GT(st.garbage_bytes, 15u);
  // all bytes random: no crash, everything accounted for
  std::string noise(5000, '\0');
  unsigned x = 12345;
  for (char& c : noise) c = static_cast<char>((x = x * 1103515245u + 12345u) >> 16);
  WitDecoderStats st2;
  Decode(noise + ReadBin(), 7, &st2);
  EXPECT_GE(st2.packets_ok, ReadExpected().size());
}

}  // namespace
}  // namespace hil::estimator::drivers

// The estimator's LinkTrack Tag_Frame0 decoder against the emulator's golden frames
// (vectors/uwb/linktrack_tag_frame0.*): every value within one LSB; garbage and bad sums counted
// and survived.
#include "hil/estimator/drivers/linktrack_decoder.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vector_files.h"

namespace hil::estimator::drivers {
namespace {

std::string ReadBin() { return hil::test::ReadVectorBytes("vectors/uwb/linktrack_tag_frame0.bin"); }

std::vector<std::vector<double>> ReadExpected() {
  return hil::test::ReadCsvNumbers("vectors/uwb/linktrack_tag_frame0.expected.csv");
}

std::vector<LinkTrackTagFrame> Decode(const std::string& b, std::size_t chunk,
                                      LinkTrackDecoderStats* st) {
  std::vector<LinkTrackTagFrame> got;
  LinkTrackDecoder dec([&](const LinkTrackTagFrame& f) { got.push_back(f); });
  for (std::size_t i = 0; i < b.size(); i += chunk) dec.Feed(std::string_view(b).substr(i, chunk));
  *st = dec.stats();
  return got;
}

TEST(LinkTrackDecoderTest, GoldenFramesWithinOneLsb) {
  const auto rows = ReadExpected();
  ASSERT_EQ(rows.size(), 10u);
  LinkTrackDecoderStats st;
  const auto got = Decode(ReadBin(), 17, &st);
  ASSERT_EQ(got.size(), rows.size());
  EXPECT_EQ(st.bad_checksum + st.garbage_bytes, 0u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    const auto& r = rows[i];
    const auto& f = got[i];
    ASSERT_EQ(r.size(), 16u);
    EXPECT_EQ(f.system_time_ms, r[0]);
    EXPECT_EQ(f.role, 2u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.p_m[k], r[1 + k], 0.0005 + 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.v_mps[k], r[4 + k], 0.00005 + 1e-12);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(f.dis_m[k], r[7 + k], 0.0005 + 1e-12);
    EXPECT_NEAR(f.angle_deg.z(), r[11], 0.005 + 1e-12);
    EXPECT_NEAR(f.gyro_radps.z(), r[12], 1e-7);
    EXPECT_NEAR(f.acc_mps2.z(), r[13], 1e-6);
    EXPECT_NEAR(f.eop_m.x(), r[14], 0.005 + 1e-12);
    EXPECT_NEAR(f.voltage_v, r[15], 0.0005 + 1e-12);
    EXPECT_NEAR(f.quat_wxyz.norm(), 1.0, 1e-6);
  }
}

TEST(LinkTrackDecoderTest, GarbageAndBadSumsAreCountedAndSurvived) {
  std::string b = ReadBin();
  b[128 * 2 + 40] ^= 0x04;                                    // frame 2: bad sum
  b.insert(128 * 5, std::string("\x55\x01\x00junk\x55", 8));  // a false header before frame 5
  b.insert(0, "noise");
  LinkTrackDecoderStats st;
  const auto got = Decode(b, 1, &st);
  EXPECT_EQ(got.size(), 9u);
  EXPECT_GE(st.bad_checksum, 2u);  // frame 2 and the false header
  EXPECT_GE(st.garbage_bytes, 5u);
  std::string noise(4000, '\0');
  unsigned x = 99;
  for (char& c : noise) c = static_cast<char>((x = x * 1103515245u + 12345u) >> 16);
  Decode(noise + ReadBin(), 3, &st);
  EXPECT_GE(st.frames_ok, 10u);
}

}  // namespace
}  // namespace hil::estimator::drivers

// The estimator's Benewake decoder against the emulator's golden session (vectors/rangefinder):
// every data frame read back within half a resolution step of the continuous value the emulator
// quantised, its validity as the manual defines it, every reply frame; the unit switch from the
// format reply; garbage, PIX text and bad checksums counted and survived.
#include "hil/estimator/drivers/benewake_decoder.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "joined_text.h"

namespace hil::estimator::drivers {
namespace {

using hil::test::Joined;

std::string SourcePath(const std::string& rel) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/" + rel;
}

struct Row {
  std::string kind, hex;
  double measured_m = 0;
  unsigned dist = 0, amp = 0;
  bool valid = false;
};

std::vector<Row> ReadExpected() {
  std::ifstream in(SourcePath("vectors/rangefinder/tf_luna_session.expected.csv"));
  std::vector<Row> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    Row r;
    r.kind = f.at(1);
    if (r.kind == "reply") {
      r.hex = f.at(7);
    } else {
      r.measured_m = std::stod(f.at(3));
      r.dist = static_cast<unsigned>(std::stoul(f.at(4)));
      r.amp = static_cast<unsigned>(std::stoul(f.at(5)));
      r.valid = f.at(7) == "1";
    }
    rows.push_back(r);
  }
  return rows;
}

std::string Hex(const BenewakeReply& r) {
  char buf[4];
  std::string s;
  const unsigned head[] = {0x5A, static_cast<unsigned>(r.payload_size + 4), r.id};
  unsigned sum = 0;
  for (const unsigned b : head) std::snprintf(buf, sizeof buf, "%02X", b), s += buf, sum += b;
  for (std::size_t k = 0; k < r.payload_size; ++k) {
    std::snprintf(buf, sizeof buf, "%02X", r.payload[k]), s += buf, sum += r.payload[k];
  }
  std::snprintf(buf, sizeof buf, "%02X", sum & 0xFFu);
  return s + buf;
}

TEST(BenewakeDecoder, ReadsTheGoldenSessionBack) {
  std::ifstream in(SourcePath("vectors/rangefinder/tf_luna_session.bin"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  const std::vector<Row> rows = ReadExpected();
  std::size_t next = 0, ranges = 0, replies = 0;
  auto advance = [&](const char* kind) {
    while (next < rows.size() && rows[next].kind != kind && rows[next].kind == "pix") ++next;
    return next < rows.size() ? &rows[next++] : nullptr;
  };
  BenewakeDecoder* self = nullptr;
  BenewakeDecoder dec(
      BenewakeModel::kTfLuna,
      [&](const BenewakeRange& r) {
        const Row* e = advance("data");
        ASSERT_NE(e, nullptr);
        ASSERT_EQ(e->kind, "data");
        EXPECT_EQ(r.dist_raw, e->dist);
        EXPECT_EQ(r.amp, e->amp);
        EXPECT_EQ(r.valid, e->valid);
        const double lsb = self->unit() == BenewakeUnit::kMm ? 0.001 : 0.01;
        if (e->valid) {
          EXPECT_NEAR(r.distance_m, e->measured_m, lsb / 2 + 1e-9);
        }
        EXPECT_DOUBLE_EQ(r.temperature_c, 40.0);
        ++ranges;
      },
      [&](const BenewakeReply& r) {
        const Row* e = advance("reply");
        ASSERT_NE(e, nullptr);
        ASSERT_EQ(e->kind, "reply");
        EXPECT_EQ(Hex(r), e->hex);
        ++replies;
      });
  self = &dec;
  std::size_t chunk = 1;
  for (std::size_t i = 0; i < bytes.size(); i += chunk, chunk = chunk % 11 + 1)
    dec.Feed(std::string_view(bytes).substr(i, chunk));
  EXPECT_EQ(next, rows.size());
  EXPECT_EQ(replies, 12u);
  EXPECT_EQ(ranges, dec.stats().ranges);
  EXPECT_GT(dec.stats().invalid_ranges, 50u);
  EXPECT_EQ(dec.stats().garbage_bytes, 6u);  // the one PIX line "0.31\r\n"
  EXPECT_EQ(dec.stats().bad_checksum, 0u);
}

TEST(BenewakeDecoder, SurvivesCorruptionAndKnowsTfminiCodes) {
  std::vector<BenewakeRange> got;
  BenewakeDecoder dec(BenewakeModel::kTfminiS, [&](const BenewakeRange& r) { got.push_back(r); });
  const std::string ok("\x59\x59\x32\x00\xE8\x03\x40\x09\x18", 9);  // 50 cm, Amp 1000, 40 °C
  std::string bad = ok;
  bad[3] = 0x01;  // checksum no longer matches
  const std::string minus_one("\x59\x59\xFF\xFF\x20\x00\x40\x09\x19", 9);  // −1, Amp 32
  dec.Feed(Joined("\x13", bad, ok, minus_one));
  ASSERT_EQ(got.size(), 2u);
  EXPECT_TRUE(got[0].valid);
  EXPECT_DOUBLE_EQ(got[0].distance_m, 0.5);
  EXPECT_FALSE(got[1].valid);
  EXPECT_EQ(dec.stats().bad_checksum, 1u);
  // the 0x13, then after the bad frame's header the 59 (not followed by 59) and 7 more bytes
  EXPECT_EQ(dec.stats().garbage_bytes, 1u + 8u);
}

// A frame's place in its stream is its time (guidanced's RangeInputs): each handler call knows
// where the frame's last byte was, across pieces and after garbage and a bad frame.
TEST(BenewakeDecoder, KnowsWhereEachFrameEnds) {
  std::vector<std::uint64_t> ends;
  const BenewakeDecoder* self = nullptr;
  BenewakeDecoder dec(BenewakeModel::kTfLuna,
                      [&](const BenewakeRange&) { ends.push_back(self->frame_end_bytes()); });
  self = &dec;
  const std::string ok("\x59\x59\x32\x00\xE8\x03\x40\x09\x18", 9);
  std::string bad = ok;
  bad[3] = 0x01;
  const std::string stream = Joined(ok, "\x13", bad, ok, ok);
  dec.Feed(stream.substr(0, 4));
  dec.Feed(stream.substr(4, 17));
  dec.Feed(stream.substr(21));
  EXPECT_EQ(ends, (std::vector<std::uint64_t>{9, 28, 37}));
  EXPECT_EQ(dec.stream_bytes(), stream.size());
}

}  // namespace
}  // namespace hil::estimator::drivers

// The $PHENC encoder sentence between guidanced and navd: formatted by hand-checked bytes, parsed
// back, and every malformed form rejected.
#include "hil/estimator/odometry/encoder_sentence.h"

#include <gtest/gtest.h>

namespace hil::estimator::odometry {
namespace {

constexpr std::int64_t kSec = 1'000'000'000;

TEST(EncoderSentence, FormatsWithTheNmeaChecksum) {
  const EncoderSentenceLine l =
      FormatEncoderSentence({(8 * 3600 + 61) * kSec + 250'000'000, 1234, -56});
  // XOR of "PHENC,080101.25,1234,-56" computed by hand
  unsigned x = 0;
  for (const char c : std::string_view("PHENC,080101.25,1234,-56"))
    x ^= static_cast<unsigned char>(c);
  char want[64];
  std::snprintf(want, sizeof want, "$PHENC,080101.25,1234,-56*%02X\r\n", x);
  EXPECT_EQ(l.view(), want);
}

TEST(EncoderSentence, RoundTripsAndRoundsToCentiseconds) {
  const EncoderSentence in{(23 * 3600 + 59 * 60 + 59) * kSec + 994'000'000, INT32_MIN, INT32_MAX};
  const EncoderSentenceLine l = FormatEncoderSentence(in);
  const std::optional<EncoderSentence> out = ParseEncoderSentence(l.view().substr(0, l.size - 2));
  ASSERT_TRUE(out);
  EXPECT_EQ(out->utc_time_of_day_ns, (23 * 3600 + 59 * 60 + 59) * kSec + 990'000'000);
  EXPECT_EQ(out->left_counts, INT32_MIN);
  EXPECT_EQ(out->right_counts, INT32_MAX);
}

TEST(EncoderSentence, RejectsMalformedLines) {
  const EncoderSentenceLine l = FormatEncoderSentence({kSec, 1, 2});
  std::string good(l.view().substr(0, l.size - 2));
  ASSERT_TRUE(ParseEncoderSentence(good));
  std::string bad = good;
  bad[8] = '9';  // checksum no longer matches
  EXPECT_FALSE(ParseEncoderSentence(bad));
  EXPECT_FALSE(ParseEncoderSentence("$GNGGA,1*00"));
  EXPECT_FALSE(ParseEncoderSentence("PHENC,000001.00,1,2*00"));
  EXPECT_FALSE(ParseEncoderSentence(""));
  // a good checksum over bad fields
  for (const char* body :
       {"PHENC,000001.0,1,2", "PHENC,250001.00,1,2", "PHENC,000001.00,1", "PHENC,000001.00,1,2,3",
        "PHENC,000001.00,x,2", "PHENC,000001.00,1,99999999999"}) {
    unsigned x = 0;
    for (const char* c = body; *c; ++c) x ^= static_cast<unsigned char>(*c);
    char line[96];
    std::snprintf(line, sizeof line, "$%s*%02X", body, x);
    EXPECT_FALSE(ParseEncoderSentence(line)) << line;
  }
}

}  // namespace
}  // namespace hil::estimator::odometry

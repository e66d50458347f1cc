#include "hil/estimator/drivers/nmea_decoder.h"

#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/drivers/nmea_epoch.h"

#include "joined_text.h"

namespace hil::estimator::drivers {
namespace {

using hil::test::Joined;

std::vector<NmeaFix> Decode(const std::vector<std::string>& pieces,
                            NmeaDecoderStats* stats = nullptr) {
  std::vector<NmeaFix> out;
  NmeaDecoder d([&](const NmeaFix& f) { out.push_back(f); });
  for (const auto& p : pieces) d.Feed(p);
  if (stats) *stats = d.stats();
  return out;
}

constexpr const char* kGga =
    "$GPGGA,191434.00,5200.17079,N,00602.17433,E,1,07,1.45,20.8,M,46.1,M,,*61\r\n";
constexpr const char* kRmc =
    "$GPRMC,191434.00,A,5200.17079,N,00602.17433,E,0.044,,040712,,,A*73\r\n";

TEST(NmeaDecoderTest, DecodesCapturedGga) {
  const auto fixes = Decode({kGga});
  ASSERT_EQ(fixes.size(), 1u);
  const NmeaFix& f = fixes[0];
  EXPECT_TRUE(f.valid);
  EXPECT_NEAR(*f.lat_deg, 52.0 + 0.17079 / 60, 1e-12);
  EXPECT_NEAR(*f.lon_deg, 6.0 + 2.17433 / 60, 1e-12);
  EXPECT_EQ(f.num_sv, 7);
  EXPECT_DOUBLE_EQ(*f.msl_altitude_m, 20.8);
  EXPECT_DOUBLE_EQ(f.altitude_step_m, 0.1);  // written with one decimal
  EXPECT_EQ(*f.utc_time_of_day_ns, (19 * 3600 + 14 * 60 + 34) * 1000000000LL);
}

TEST(NmeaDecoderTest, SurvivesSplitReadsGarbageAndBadChecksums) {
  std::string bad = kGga;
  bad[20] = '9';  // corrupt a digit: checksum no longer matches
  const std::string stream = Joined("\xB5\x62\x01\x02junk", kRmc, bad, "noise", kGga);
  std::vector<std::string> pieces;
  for (std::size_t i = 0; i < stream.size(); i += 7) pieces.push_back(stream.substr(i, 7));
  NmeaDecoderStats st;
  const auto fixes = Decode(pieces, &st);
  ASSERT_EQ(fixes.size(), 2u);
  EXPECT_EQ(fixes[0].kind, NmeaFix::Kind::kRmc);
  EXPECT_EQ(fixes[1].kind, NmeaFix::Kind::kGga);
  EXPECT_EQ(st.bad_checksum, 1u);
  EXPECT_EQ(st.garbage_bytes, 13u);  // 4 binary + "junk" + "noise"
}

TEST(NmeaDecoderTest, NoFixSentencesAreNotValid) {
  const auto fixes = Decode({"$GPGGA,191418.00,,,,,0,00,99.99,,,,,,*62\r\n",
                             "$GPRMC,191418.00,V,,,,,,,040712,,,N*79\r\n"});
  ASSERT_EQ(fixes.size(), 2u);
  EXPECT_FALSE(fixes[0].valid);
  EXPECT_FALSE(fixes[1].valid);
  EXPECT_EQ(*fixes[1].year, 2012);
}

TEST(NmeaEpochTest, JoinsRmcDateWithGgaPosition) {
  NmeaEpochAssembler a;
  std::optional<NmeaMeasurement> m;
  for (const auto& f : Decode({kRmc, kGga})) {
    if (auto r = a.Add(f)) m = r;
  }
  ASSERT_TRUE(m);
  // 2012-07-04T19:14:34Z
  EXPECT_EQ(m->tov_unix_ns, 1341429274LL * 1000000000LL);
  EXPECT_NEAR(m->height_m, 20.8 + 46.1, 1e-9);
  EXPECT_DOUBLE_EQ(m->altitude_step_m, 0.1);
  EXPECT_NEAR(*m->speed_mps, 0.044 * 1852.0 / 3600.0, 1e-12);
}

// The real u-blox 5 captures of gpsd's regression corpus are decoded and compared with gpsd's own
// output, sentence by sentence and epoch by epoch, in tests/estimator/gpsd/ (label golden).

}  // namespace
}  // namespace hil::estimator::drivers

namespace hil::estimator::drivers {
namespace {

// Found by nmea_decoder_fuzz: "99959.000,E" decoded as a longitude of 999.98°.
TEST(NmeaDecoderTest, RejectsCoordinatesOffTheEarth) {
  NmeaDecoderStats st;
  const std::string body = "GPGGA,191434.00,5200.17079,N,99959.00000,E,1,07,1.45,20.8,M,46.1,M,,";
  std::uint8_t sum = 0;
  for (char c : body) sum ^= static_cast<std::uint8_t>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X", sum);
  const auto fix = NmeaDecoder::ParseSentence("$" + body + tail, &st);
  ASSERT_TRUE(fix);
  EXPECT_FALSE(fix->lon_deg.has_value());
  EXPECT_FALSE(fix->valid);
}

}  // namespace
}  // namespace hil::estimator::drivers

namespace hil::estimator::drivers {
namespace {

// issue 39: a receiver's height error scales with its VDOP, which GSA reports (the emulated RTK
// rover's sky: HDOP 2.19, VDOP 6.31); navd read GGA's HDOP only and modelled the height at a third
// of its error. GSA's VDOP joins the GGA epochs that follow it, and the geoid separation's step is
// kept (its rounding is one offset for the site).
TEST(NmeaEpochTest, GsaVdopAndGeoidStepJoinTheEpoch) {
  constexpr const char* kGsa = "$GPGSA,A,3,30,05,20,08,32,27,19,07,,,,,6.68,2.19,6.31*03\r\n";
  constexpr const char* kGsaNoFix = "$GPGSA,A,1,,,,,,,,,,,,,99.99,99.99,99.99*30\r\n";
  NmeaDecoderStats stats;
  const auto fixes = Decode({kRmc, kGga, kGsa, kGsaNoFix}, &stats);
  ASSERT_EQ(fixes.size(), 4u);
  EXPECT_EQ(stats.unsupported, 0u);
  EXPECT_EQ(fixes[2].kind, NmeaFix::Kind::kGsa);
  EXPECT_FALSE(fixes[2].valid);  // no position
  EXPECT_DOUBLE_EQ(*fixes[2].vdop, 6.31);
  EXPECT_DOUBLE_EQ(*fixes[2].hdop, 2.19);
  EXPECT_FALSE(fixes[3].vdop);  // no 3-D solution: no VDOP
  EXPECT_DOUBLE_EQ(fixes[1].geoid_step_m, 0.1);
  // an epoch after a GSA with a 3-D solution carries its VDOP
  NmeaEpochAssembler a;
  std::optional<NmeaMeasurement> m;
  for (const auto& f : Decode({kRmc, kGga, kGsa, kRmc, kGga})) {
    if (auto r = a.Add(f)) m = r;
  }
  ASSERT_TRUE(m);
  EXPECT_DOUBLE_EQ(m->vdop.value_or(0.0), 6.31);
  EXPECT_DOUBLE_EQ(m->geoid_step_m, 0.1);
  // AND one after a GSA without a solution does not
  for (const auto& f : Decode({kGsaNoFix, kRmc, kGga})) {
    if (auto r = a.Add(f)) m = r;
  }
  EXPECT_FALSE(m->vdop);
}

}  // namespace
}  // namespace hil::estimator::drivers

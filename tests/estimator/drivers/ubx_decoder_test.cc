#include "hil/estimator/drivers/ubx_decoder.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

void Le(std::string& s, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
std::string Frame(std::uint8_t cls, std::uint8_t id, const std::string& payload) {
  char buf[256];
  const std::size_t n = UbxDecoder::Encode(cls, id, payload, buf, sizeof buf);
  return std::string(buf, n);
}
std::string PosLlh(std::uint32_t itow) {
  std::string p;
  Le(p, itow, 4);
  Le(p, static_cast<std::uint32_t>(505979765), 4);  // lon 50.5979765
  Le(p, static_cast<std::uint32_t>(354796096), 4);  // lat 35.4796096
  Le(p, 1301250, 4);                                // height 1301.25 m
  Le(p, 1280000, 4);
  Le(p, 2500, 4);  // hAcc 2.5 m
  Le(p, 4000, 4);
  return Frame(0x01, 0x02, p);
}
std::string VelNed(std::uint32_t itow) {
  std::string p;
  Le(p, itow, 4);
  Le(p, 30, 4);                               // N 0.30
  Le(p, static_cast<std::uint32_t>(-40), 4);  // E −0.40
  Le(p, 5, 4);                                // D 0.05
  Le(p, 50, 4);
  Le(p, 50, 4);
  Le(p, 0, 4);
  Le(p, 20, 4);  // sAcc 0.20
  Le(p, 0, 4);
  return Frame(0x01, 0x12, p);
}
std::string Sol(std::uint32_t itow, std::uint8_t fix, std::uint8_t flags) {
  std::string p;
  Le(p, itow, 4);
  Le(p, static_cast<std::uint32_t>(-1500), 4);  // fTOW −1.5 µs
  Le(p, 1744, 2);
  p.push_back(static_cast<char>(fix));
  p.push_back(static_cast<char>(flags));
  p.append(35, '\0');
  p.push_back(7);  // numSV
  p.append(4, '\0');
  return Frame(0x01, 0x06, p);
}

TEST(UbxDecoderTest, EncodeMatchesReferenceCfgMsgFrame) {
  // CFG-MSG NAV-SOL rate 1, as listed in ublox5.md §1
  EXPECT_EQ(Frame(0x06, 0x01, std::string("\x01\x06\x01", 3)),
            std::string("\xB5\x62\x06\x01\x03\x00\x01\x06\x01\x12\x4F", 11));
}

TEST(UbxDecoderTest, AssemblesAnEpochFromMixedSplitStream) {
  // GIVEN SOL, NMEA text, a corrupted POSLLH, garbage, VELNED then the good POSLLH, one byte per
  // read
  std::string bad = PosLlh(86400000);
  bad[10] ^= 0x01;
  const std::string stream = Sol(86400000, 3, 0x0D) + "$GPGGA,foo*00\r\n" + bad + "\x01\xB5\x02" +
                             VelNed(86400000) + PosLlh(86400000);
  UbxEpochAssembler asm_;
  std::vector<GnssSample> out;
  UbxDecoder d([&](const UbxMessage& m) {
    for (const GnssSample& g : asm_.Add(m)) out.push_back(g);
  });
  for (char c : stream) d.Feed(std::string_view(&c, 1));
  // THEN one fix on GPS time with position, accuracy and NED→ENU velocity
  EXPECT_EQ(d.stats().bad_checksum, 1u);
  EXPECT_EQ(d.stats().frames_ok, 3u);
  ASSERT_EQ(out.size(), 1u);
  const GnssSample& g = out[0];
  EXPECT_EQ(ToNs(g.t), 1744LL * 604800LL * kNsPerSecond + 86400LL * kNsPerSecond - 1500);
  EXPECT_NEAR(g.position.lat_deg, 35.4796096, 1e-9);
  EXPECT_NEAR(g.position.lon_deg, 50.5979765, 1e-9);
  EXPECT_NEAR(g.position.height_m, 1301.25, 1e-9);
  EXPECT_NEAR(g.pos_std_enu_m.x(), 2.5 / std::sqrt(2.0), 1e-9);
  ASSERT_TRUE(g.has_velocity);
  EXPECT_NEAR(g.vel_enu_mps.x(), -0.40, 1e-12);
  EXPECT_NEAR(g.vel_enu_mps.y(), 0.30, 1e-12);
  EXPECT_NEAR(g.vel_enu_mps.z(), -0.05, 1e-12);
  EXPECT_EQ(g.num_sv, 7);
}

TEST(UbxDecoderTest, NoFixIsNotReportedAndIncompleteEpochFlushesOnNextItow) {
  UbxEpochAssembler a;
  std::vector<GnssSample> out;
  UbxDecoder d([&](const UbxMessage& msg) {
    for (const GnssSample& g : a.Add(msg)) out.push_back(g);
  });
  d.Feed(Sol(1000, 0, 0x0C) + PosLlh(1000) + VelNed(1000));  // no fix
  d.Feed(Sol(2000, 3, 0x0D) + PosLlh(2000));                 // no VELNED this epoch
  EXPECT_TRUE(out.empty());
  d.Feed(PosLlh(3000));       // the next epoch flushes the previous one: VELNED missing, so the
  ASSERT_EQ(out.size(), 1u);  // velocity is NAV-SOL's ECEF velocity (zero in this SOL)
  EXPECT_TRUE(out[0].has_velocity);
  EXPECT_EQ(out[0].vel_enu_mps.norm(), 0.0);
  EXPECT_EQ(out[0].vel_std_enu_mps.x(), 0.01);  // SOL sAcc 0, floored at 1 cm/s
}

// NAV-SOL of navisys-gr701w.log at 2024-03-28T15:14:05Z (GPS week 2307): ECEF in cm and cm/s
std::string SolEcef(std::uint32_t itow, std::uint8_t fix, std::uint8_t flags) {
  std::string p;
  Le(p, itow, 4);
  Le(p, 0, 4);  // fTOW
  Le(p, 2307, 2);
  p.push_back(static_cast<char>(fix));
  p.push_back(static_cast<char>(flags));
  for (std::int32_t v : {-200169112, -392507405, 459654666})
    Le(p, static_cast<std::uint32_t>(v), 4);
  Le(p, 2463, 4);  // pAcc 24.63 m
  for (std::int32_t v : {38, -22, -2}) Le(p, static_cast<std::uint32_t>(v), 4);
  Le(p, 105, 4);  // sAcc 1.05 m/s
  Le(p, 250, 2);  // pDOP 2.5
  p.push_back(0);
  p.push_back(5);  // numSV
  p.append(4, '\0');
  return Frame(0x01, 0x06, p);
}

TEST(UbxDecoderTest, ReceiverSendingOnlyNavSolGivesPositionAndVelocityFromEcef) {
  // GIVEN a receiver that sends NAV-SOL (no POSLLH, no VELNED) each second
  UbxEpochAssembler a;
  std::vector<GnssSample> out;
  UbxDecoder d([&](const UbxMessage& m) {
    for (const GnssSample& g : a.Add(m)) out.push_back(g);
  });
  const std::uint32_t itow = 4 * 86400000 + 15 * 3600000 + 14 * 60000 + 23000;  // Thu 15:14:23 GPS
  d.Feed(SolEcef(itow, 3, 0x0D));
  EXPECT_TRUE(out.empty());  // what the receiver sends per epoch is not known yet
  d.Feed(SolEcef(itow + 1000, 3, 0x0D));
  ASSERT_EQ(out.size(), 2u);  // the first epoch, flushed by the second, and the second (learned:
                              // this receiver sends NAV-SOL alone)
  d.Feed(SolEcef(itow + 2000, 2, 0x0D));
  ASSERT_EQ(out.size(), 3u);  // NAV-SOL alone completes an epoch at once
  // THEN position, height and velocity equal gpsd's decoding of the same message (.chk:
  // lat 46.404648618, lon -117.020462010, altHAE 232.9577, velN -0.031, velE 0.438, velD -0.002)
  const GnssSample& g = out[0];
  EXPECT_EQ(ToNs(g.t), 2307LL * 604800LL * kNsPerSecond + itow * 1'000'000LL);
  EXPECT_NEAR(g.position.lat_deg, 46.404648618, 1e-9);
  EXPECT_NEAR(g.position.lon_deg, -117.020462010, 1e-9);
  EXPECT_NEAR(g.position.height_m, 232.9577, 1e-4);
  EXPECT_NEAR(g.pos_std_enu_m.x(), 24.63 / std::sqrt(3.0), 1e-9);
  ASSERT_TRUE(g.has_velocity);
  EXPECT_NEAR(g.vel_enu_mps.x(), 0.438, 5e-4);
  EXPECT_NEAR(g.vel_enu_mps.y(), -0.031, 5e-4);
  EXPECT_NEAR(g.vel_enu_mps.z(), 0.002, 5e-4);
  ASSERT_TRUE(g.ground_speed_mps);
  EXPECT_NEAR(*g.ground_speed_mps, 0.440, 5e-4);
  EXPECT_EQ(g.num_sv, 5);
  EXPECT_EQ(g.fix_dim, 3);
  // a 2-D fix: the height is the receiver's held value, not a measurement
  EXPECT_EQ(out[2].fix_dim, 2);
  EXPECT_EQ(out[2].pos_std_enu_m.z(), UbxEpochAssembler::kHeldHeightStd_m);
}

TEST(UbxDecoderTest, NavSolWithGpsFixOkClearIsNoFix) {
  UbxEpochAssembler a;
  std::vector<GnssSample> out;
  UbxDecoder d([&](const UbxMessage& m) {
    for (const GnssSample& g : a.Add(m)) out.push_back(g);
  });
  d.Feed(SolEcef(1000, 3, 0x0D) + SolEcef(2000, 3, 0x0C) + SolEcef(3000, 3, 0x0D));
  ASSERT_EQ(out.size(), 2u);  // the epoch at 2000 (3-D, gpsFixOk clear) is dropped
  EXPECT_EQ(ToNs(out[1].t) % (604800LL * kNsPerSecond), 3000 * 1'000'000LL);
}

// Issue 40 (minor): navd in UBX mode stamped its solutions' UTC with its configured leap seconds
// even when the receiver reported a valid value. NAV-TIMEGPS with the leapS valid flag decides;
// without the flag (a receiver that has not decoded the almanac yet) the configured value stays.
TEST(UbxDecoderTest, ReceiverLeapSecondsOverrideTheConfiguredOnceValid) {
  UbxEpochAssembler a;
  EXPECT_EQ(a.UtcLeapSeconds(18), 18);
  const auto time_gps = [](int leap_s, std::uint8_t valid) {
    std::string p;
    Le(p, 1000, 4);
    Le(p, 0, 4);
    Le(p, 1744, 2);
    Le(p, static_cast<std::uint64_t>(leap_s), 1);
    Le(p, valid, 1);
    Le(p, 20, 4);
    return Frame(0x01, 0x20, p);
  };
  std::vector<UbxMessage> msgs;
  UbxDecoder dec([&](const UbxMessage& m) { msgs.push_back(m); });
  dec.Feed(time_gps(14, 0x03));  // tow and week valid, leap seconds the firmware's default
  ASSERT_EQ(msgs.size(), 1u);
  a.Add(msgs[0]);
  EXPECT_EQ(a.UtcLeapSeconds(18), 18) << "not valid yet: the configured value";
  dec.Feed(time_gps(16, 0x07));
  ASSERT_EQ(msgs.size(), 2u);
  a.Add(msgs[1]);
  EXPECT_EQ(a.UtcLeapSeconds(18), 16) << "the receiver's valid value";
  EXPECT_EQ(a.UtcLeapSeconds(17), 16);
}

}  // namespace
}  // namespace hil::estimator::drivers

#include "hil/estimator/outputs/n2k_encoder.h"

#include <cmath>

#include <gtest/gtest.h>

#include "hil/estimator/outputs/nmea0183_writer.h"

namespace hil::estimator::outputs {
namespace {

std::string Hex(const CanFrame& f) {
  return CandumpLine(f, 0, "x").substr(std::string("(0.000000) x ").size());
}

TEST(N2kEncoderTest, PositionRapidMatchesReferenceFrame) {
  // reference: can_and_transports.md §6, 129025 lat 52.1234568 lon 5.9876543 from SA 0x80
  EXPECT_EQ(Hex(EncodePositionRapid(52.1234568, 5.9876543, 0x80)), "09F80180#8868111FBFA49103\n");
}

TEST(N2kEncoderTest, CogSogMatchesReferenceFrame) {
  EXPECT_EQ(Hex(EncodeCogSogRapid(7, M_PI / 2, 2.5, 0x80)), "09F80280#07FC5C3DFA00FFFF\n");
}

TEST(N2kEncoderTest, GnssPositionIsSevenFastPacketFramesThatReassemble) {
  const FastPacket fp =
      EncodeGnssPosition(3, 15866, 28800.5, 35.4796096, -50.5979765, 1301.25, 6, 8, 1.2, 5, 0x80);
  ASSERT_EQ(fp.count, 7);
  EXPECT_EQ(fp.frames[0].id, 0x0DF80580u);
  EXPECT_EQ(fp.frames[0].data[0], 5 << 5);
  EXPECT_EQ(fp.frames[0].data[1], 43);
  std::vector<std::uint8_t> p(fp.frames[0].data.begin() + 2, fp.frames[0].data.end());
  for (int i = 1; i < fp.count; ++i) {
    EXPECT_EQ(fp.frames[i].data[0], (5 << 5) | i);
    p.insert(p.end(), fp.frames[i].data.begin() + 1, fp.frames[i].data.end());
  }
  p.resize(43);
  const auto le = [&](int at, int n) {
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = (v << 8) | p[static_cast<std::size_t>(at + i)];
    return v;
  };
  EXPECT_EQ(le(1, 2), 15866u);
  EXPECT_EQ(le(3, 4), 288005000u);
  EXPECT_NEAR(static_cast<double>(static_cast<std::int64_t>(le(7, 8))) * 1e-16, 35.4796096, 1e-12);
  EXPECT_NEAR(static_cast<double>(static_cast<std::int64_t>(le(15, 8))) * 1e-16, -50.5979765,
              1e-12);
  EXPECT_EQ(static_cast<std::int64_t>(le(23, 8)), 1301250000);
  EXPECT_EQ(p[31] >> 4, 6);  // method: estimated (dead reckoning)
  EXPECT_EQ(p[33], 8);
}

TEST(N2kEncoderTest, HeadingAndAttitude) {
  const CanFrame h = EncodeVesselHeading(1, -0.1, 0x80);  // wraps to 2π − 0.1
  EXPECT_EQ(h.id, 0x09F11280u);
  EXPECT_EQ(h.data[1] | (h.data[2] << 8), std::lround((2 * M_PI - 0.1) * 1e4));
  const CanFrame a = EncodeAttitude(1, 1.0, -0.02, 0.03, 0x80);
  EXPECT_EQ(a.id, 0x0DF11980u);
  EXPECT_EQ(static_cast<std::int16_t>(a.data[3] | (a.data[4] << 8)), -200);
  EXPECT_EQ(static_cast<std::int16_t>(a.data[5] | (a.data[6] << 8)), 300);
}

TEST(Nmea0183WriterTest, SentencesCarryChecksumsAndValues) {
  NavOutput o;
  o.valid = true;
  o.position = {35.5, -50.25, 1300.0};
  o.v_N_mps = Eigen::Vector3d(0, 1, 0);
  o.has_attitude = true;
  o.q_NB = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());  // body x north
  const std::string s = FormatNmea0183(o, (15866LL * 86400 + 3600) * 1000000000LL);
  EXPECT_NE(s.find("$GNRMC,010000.00,A,3530.0000000,N,05015.0000000,W,1.944,0.00,100613,,,A*"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("$GNGGA,010000.00,3530.0000000,N,05015.0000000,W,1,08,1.0,1300.000,M,0.0,M,,*"),
            std::string::npos);
  EXPECT_NE(s.find("$GNHDT,0.00,T*"), std::string::npos);
  EXPECT_EQ(
      NmeaSentence("GPGGA,191434.00,5200.17079,N,00602.17433,E,1,07,1.45,20.8,M,46.1,M,,"),
      "$GPGGA,191434.00,5200.17079,N,00602.17433,E,1,07,1.45,20.8,M,46.1,M,,*61\r\n");  // a
                                                                                        // captured
                                                                                        // sentence
}

}  // namespace
}  // namespace hil::estimator::outputs

// RTCM 3 station messages 1005/1006: the standard's 1005 example re-encoded from its values gives
// its bytes, every field round-trips, 1006 adds the antenna height, and out-of-range fields throw.
#include "hil/firmware_emu/rtk/rtcm3_station.h"

#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

#include "hex_bytes.h"

namespace hil::rtcm3 {
namespace {

std::string Hex(const std::string& s) { return hil::test::HexBytes(s, {.upper = true}); }

StationInfo Example() {
  StationInfo s;
  s.station_id = 2003;
  s.arp_E_m = {1114104.5999, -4850729.7108, 3975521.4643};
  s.gps = true;
  s.glonass = false;
  s.galileo = false;
  s.single_oscillator = false;
  return s;
}

TEST(Rtcm3Station, StandardExample1005) {
  EXPECT_EQ(Hex(Frame(Encode1005(Example()))),
            "D300133ED7D30202980EDEEF34B4BD62AC0941986F33360B98");
}

TEST(Rtcm3Station, RoundTrip1005And1006) {
  StationInfo s = Example();
  s.antenna_height_m = 1.8765;
  s.itrf_year = 20;
  s.glonass = true;
  s.quarter_cycle = 2;
  const std::string b5 = Encode1005(s), b6 = Encode1006(s);
  EXPECT_EQ(b5.size(), 19U);  // 152 bits
  EXPECT_EQ(b6.size(), 21U);  // 168 bits
  EXPECT_EQ(MessageNumber(b6), 1006);
  const StationInfo d5 = DecodeStation(b5), d6 = DecodeStation(b6);
  EXPECT_EQ(d6.station_id, 2003);
  EXPECT_EQ(d6.itrf_year, 20);
  EXPECT_TRUE(d6.gps && d6.glonass && !d6.galileo);
  EXPECT_EQ(d6.quarter_cycle, 2);
  EXPECT_LT((d6.arp_E_m - s.arp_E_m).cwiseAbs().maxCoeff(), 0.5e-4);
  EXPECT_NEAR(d6.antenna_height_m, 1.8765, 1e-9);
  EXPECT_EQ(d5.antenna_height_m, 0.0);
  EXPECT_EQ(d5.arp_E_m, d6.arp_E_m);
}

TEST(Rtcm3Station, NegativeCoordinatesUseTwosComplement) {
  StationInfo s;
  s.arp_E_m = {-0.0001, -6378137.0, -1.0};
  const StationInfo d = DecodeStation(Encode1005(s));
  EXPECT_NEAR(d.arp_E_m.x(), -0.0001, 1e-12);
  EXPECT_NEAR(d.arp_E_m.y(), -6378137.0, 1e-9);
  EXPECT_NEAR(d.arp_E_m.z(), -1.0, 1e-12);
}

TEST(Rtcm3Station, OutOfRangeFieldsThrow) {
  StationInfo s;
  s.station_id = 4096;
  EXPECT_THROW(Encode1005(s), std::out_of_range);
  s.station_id = 1;
  s.antenna_height_m = 6.6;  // DF028 holds at most 6.5535 m
  EXPECT_THROW(Encode1006(s), std::out_of_range);
  s.antenna_height_m = 0;
  s.arp_E_m.x() = 2.8e7;  // DF025 holds ±13 743 895 m
  EXPECT_THROW(Encode1005(s), std::out_of_range);
  EXPECT_THROW(DecodeStation("\x3E\xE0"), std::invalid_argument);
}

}  // namespace
}  // namespace hil::rtcm3

// The ZED-F9P device through its UART1: a host's CFG-VALSET enables NAV-PVT and changes the
// navigation rate (ACK-ACK ready 10 ms after its last byte has arrived at 38400 Bd), an unknown
// key is NAKed and changes nothing, VALGET reads back; NMEA output off by VALSET; the host's RTCM
// (an NTRIP client writing the base's stream to UART1 each second) brings float then fixed.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_frame.h"

#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;

std::string ValSet(const std::vector<std::pair<std::uint32_t, std::uint64_t>>& kvs) {
  std::vector<std::uint8_t> p{0, 1, 0, 0};  // version 0, RAM
  for (const auto& [id, v] : kvs) {
    for (int k = 0; k < 4; ++k) p.push_back(static_cast<std::uint8_t>(id >> (8 * k)));
    for (std::size_t k = 0; k < gnss::ubx::F9ValueBytes(id); ++k)
      p.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  return gnss::ubx::Frame(0x06, 0x8A, p);
}

int Count(const std::vector<SerialMessage>& sent, const std::string& name) {
  int n = 0;
  for (const SerialMessage& m : sent) n += m.name == name ? 1 : 0;
  return n;
}

TEST(ZedF9pDevice, ValsetThroughTheUartAcksAndApplies) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.radio_base.reset();
  ZedF9pDevice dev(c, 3);
  auto sent = test::RunUntil(dev, TimeFromSeconds(2.3));
  EXPECT_EQ(Count(sent, "UBX-NAV-PVT"), 0);
  EXPECT_EQ(Count(sent, "NMEA-GGA"), 3);
  DeviceOutput out;
  const std::string cmd =
      ValSet({{key::kNavPvtUart1, 1}, {key::kRateMeas, 200}, {key::kUart1OutNmea, 0}});
  dev.OnHostBytes(0, TimeFromSeconds(2.3), cmd, out);
  ASSERT_EQ(out.serial.size(), 1U);
  EXPECT_EQ(out.serial[0].name, "UBX-ACK-ACK");
  EXPECT_TRUE(out.serial[0].reply);
  // its last byte arrives 10 bit times × length at 38400 Bd after 2.3 s, the ACK 10 ms later
  const double t_arrival = 2.3 + static_cast<double>(cmd.size()) * 10.0 / 38400.0;
  EXPECT_NEAR(ToSeconds(out.serial[0].t_ready - Time{}), t_arrival + 0.010, 1e-6);
  sent = test::RunUntil(dev, TimeFromSeconds(4));
  EXPECT_EQ(Count(sent, "UBX-NAV-PVT"), 8) << "5 Hz from 2.4 s to 3.8 s";
  EXPECT_EQ(Count(sent, "NMEA-GGA"), 0);

  out.clear();
  dev.OnHostBytes(0, TimeFromSeconds(4.1), ValSet({{key::kRateMeas, 1000}, {0x20910999, 1}}), out);
  ASSERT_EQ(out.serial.size(), 1U);
  EXPECT_EQ(out.serial[0].name, "UBX-ACK-NAK");
  EXPECT_EQ(dev.config_db().Get(key::kRateMeas), 200U);

  out.clear();
  std::vector<std::uint8_t> get{0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) get.push_back(static_cast<std::uint8_t>(key::kRateMeas >> (8 * k)));
  dev.OnHostBytes(0, TimeFromSeconds(4.5), gnss::ubx::Frame(0x06, 0x8B, get), out);
  ASSERT_EQ(out.serial.size(), 2U);
  EXPECT_EQ(out.serial[0].name, "UBX-CFG-VALGET");
  EXPECT_EQ(static_cast<unsigned char>(out.serial[0].bytes[14]), 200);  // payload 8: value
  EXPECT_EQ(out.serial[1].name, "UBX-ACK-ACK");
}

TEST(ZedF9pDevice, HostRtcmOnUart1BringsFloatThenFixed) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.radio_base.reset();  // corrections: host
  ZedF9pDevice dev(c, 3);
  RtkBaseDevice base(test::KarajBase(rtcm3::MsmKind::kMsm4), 9);
  DeviceOutput out;
  for (int k = 0; k < 20; ++k) {
    test::RunUntil(dev, TimeFromSeconds(k + 0.5));
    std::string bytes;
    for (const SerialMessage& m : base.EncodeEpoch(TimeFromSeconds(k))) bytes += m.bytes;
    dev.OnHostBytes(0, TimeFromSeconds(k + 0.5), bytes, out);  // the NTRIP client's write
  }
  test::RunUntil(dev, TimeFromSeconds(20));
  const auto& tl = dev.timeline();
  ASSERT_EQ(tl.size(), 3U);
  EXPECT_EQ(tl[1].carr_soln, gnss::ubx::CarrSoln::kFloat);
  EXPECT_DOUBLE_EQ(ToSeconds(tl[1].t - Time{}), 2.0);  // first frames ≈ 0.6 s
  EXPECT_EQ(tl[2].carr_soln, gnss::ubx::CarrSoln::kFixed);
  EXPECT_DOUBLE_EQ(ToSeconds(tl[2].t - Time{}), 12.0);
  EXPECT_EQ(dev.rover_statistics().rtcm_crc_failed, 0U);
}

}  // namespace
}  // namespace hil::rtk

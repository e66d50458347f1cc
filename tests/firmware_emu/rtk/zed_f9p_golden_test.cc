// Golden capture of the ZED-F9P rover's first 14 seconds: still at the Karaj site, its base 2 km
// away on the radio (UART2), UART1 configured (saved in Flash) for NAV-PVT, NAV-HPPOSLLH,
// NAV-RELPOSNED and RXM-RTCM each epoch and NAV-SAT every 5 epochs beside the default NMEA 4.10
// set, a MON-VER poll answered at 0.5 s. It covers the standalone fix (carrSoln 0), the float
// (from 2 s) and the fixed solution (from 12 s): every message with its time, bytes (UBX hex,
// NMEA text) and, for NAV-PVT, the decoded fields. vectors/gnss/zed_f9p_first_seconds.golden is
// regenerated and compared (HIL_REGEN_VECTORS=1 rewrites it); provenance in vectors/gnss/README.md.
#include <cstdio>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_frame.h"

#include "golden_file.h"
#include "hex_bytes.h"
#include "ubx_le_field.h"
#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;
using test::Le;

std::string Hex(const std::string& b) { return hil::test::HexBytes(b); }

// NAV-PVT's fields as the interface description lays them out.
std::string PvtFields(std::string_view p) {
  std::ostringstream s;
  s << "  iTOW=" << Le(p, 0, 4, false) << " fixType=" << Le(p, 20, 1, false)
    << " gnssFixOK=" << (Le(p, 21, 1, false) & 1) << " diffSoln=" << (Le(p, 21, 1, false) >> 1 & 1)
    << " carrSoln=" << (Le(p, 21, 1, false) >> 6) << " numSV=" << Le(p, 23, 1, false)
    << " lon=" << Le(p, 24, 4, true) << " lat=" << Le(p, 28, 4, true)
    << " height=" << Le(p, 32, 4, true) << " hAcc=" << Le(p, 40, 4, false)
    << " vAcc=" << Le(p, 44, 4, false) << " headMot=" << Le(p, 64, 4, true)
    << " lastCorrectionAge=" << (Le(p, 78, 2, false) >> 1 & 0xF) << "\n";
  return s.str();
}

ZedF9pConfig GoldenRover() {
  ZedF9pConfig c = test::RoverWithRadio();
  c.flash = {{key::kNavPvtUart1, 1},  {key::kNavHpposllhUart1, 1}, {key::kNavRelposnedUart1, 1},
             {key::kRxmRtcmUart1, 1}, {key::kNavSatUart1, 5},      {key::kUart1Baudrate, 115200}};
  return c;
}

TEST(ZedF9pGolden, FirstSeconds) {
  ZedF9pDevice dev(GoldenRover(), 3);
  std::vector<SerialMessage> sent = test::RunUntil(dev, TimeFromSeconds(0.5));
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.5),
                  gnss::ubx::Frame(0x0A, 0x04, std::vector<std::uint8_t>{}), out);  // MON-VER poll
  for (auto& m : out.serial) sent.push_back(std::move(m));
  for (auto& m : test::RunUntil(dev, TimeFromSeconds(14))) sent.push_back(std::move(m));
  std::ostringstream g;
  g << "# ZED-F9P emulator, first 14 s (tests/firmware_emu/rtk/zed_f9p_golden_test.cc; regenerate\n"
       "# with HIL_REGEN_VECTORS=1). Per message: t_ready in ms, name, bytes (UBX hex, NMEA "
       "text).\n";
  for (const SerialMessage& m : sent) {
    g << ToNs(m.t_ready) / 1000000 << " " << m.name << " ";
    if (m.name.rfind("NMEA", 0) == 0) {
      g << m.bytes.substr(0, m.bytes.size() - 2) << "\n";
      continue;
    }
    g << Hex(m.bytes) << "\n";
    if (m.name == "UBX-NAV-PVT") g << PvtFields(std::string_view(m.bytes).substr(6, 92));
  }
  hil::test::CheckOrWriteGolden("vectors/gnss/zed_f9p_first_seconds.golden", g.str());
}

// The golden's meaning, checked against the inputs rather than against itself.
TEST(ZedF9pGolden, MessagesSayWhatTheStateIs) {
  ZedF9pDevice dev(GoldenRover(), 3);
  const auto sent = test::RunUntil(dev, TimeFromSeconds(14));
  int pvt = 0;
  for (const SerialMessage& m : sent) {
    const double t_s = ToSeconds(m.t_ready - Time{});
    if (t_s < 1) continue;  // the hot start's first epoch has no fix yet
    if (m.name == "NMEA-GGA") {
      // field 6 of GGA: 1 before float, 5 float (2 s…), 4 fixed (12 s…)
      std::vector<std::string> f;
      std::stringstream ss(m.bytes);
      for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
      ASSERT_GT(f.size(), 14U);
      EXPECT_EQ(f[0], "$GNGGA");
      EXPECT_EQ(f[6], t_s < 2 ? "1" : t_s < 12 ? "5" : "4") << m.bytes;
      if (t_s > 2) {
        EXPECT_EQ(f[14].substr(0, 4), "1234") << "the base's station id";
      }
    }
    if (m.name != "UBX-NAV-PVT") continue;
    ++pvt;
    const std::string_view p = std::string_view(m.bytes).substr(6, 92);
    EXPECT_EQ(Le(p, 20, 1, false), 3);
    EXPECT_EQ(Le(p, 21, 1, false) >> 6, t_s < 2 ? 0 : t_s < 12 ? 1 : 2);
    EXPECT_NEAR(static_cast<double>(Le(p, 28, 4, true)) * 1e-7, test::kRoverLat_deg,
                t_s < 2    ? 1e-4
                : t_s < 12 ? 2e-5
                           : 1e-6);
  }
  EXPECT_EQ(pvt, 13);  // 1 s … 13 s
}

}  // namespace
}  // namespace hil::rtk

// navd's GNSS input (estimator/navd/gnss_receivers.h) on a u-blox 9 rover's line that carries NMEA
// and UBX NAV-PVT together: the UBX frames are framed out of the NMEA stream (no garbage), and the
// NAV-PVT of an epoch is fused in place of that epoch's GGA, with the receiver's hAcc/vAcc/sAcc
// (navd's ubx_acc_scale and floors) and carrSoln as the fix quality; with gnss_nav_pvt = false
// the GGA is fused as before with the configured RTK σ.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/navd/navd_config.h"

#include "gnss_receivers.h"

namespace hil::navd {
namespace {

namespace est = hil::estimator;

void PutLe(std::string& p, std::size_t at, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) p[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}

// NAV-PVT of 2026-06-10 08:00:ss (iTOW: Wednesday, GPS = UTC + 18 s), an RTK float fix (carrSoln
// 1, diffSoln) at the given hAcc (mm) and sAcc (mm/s).
std::string NavPvtFloat(int second, std::uint32_t h_acc_mm, std::uint32_t s_acc_mm) {
  std::string p(92, '\0');
  const std::uint32_t itow_ms = (3U * 86400U + 8U * 3600U + second + 18U) * 1000U;
  PutLe(p, 0, itow_ms, 4);
  PutLe(p, 4, 2026, 2), p[6] = 6, p[7] = 10, p[8] = 8, p[9] = 0, p[10] = static_cast<char>(second);
  p[11] = 0x07;                               // validDate, validTime, fullyResolved
  p[20] = 3, p[21] = 0x01 | 0x02 | (1 << 6);  // 3-D; gnssFixOK, diffSoln, carrSoln float
  p[23] = 12;                                 // numSV
  PutLe(p, 24, static_cast<std::uint32_t>(505979765), 4);  // lon 50.5979765°
  PutLe(p, 28, static_cast<std::uint32_t>(354796096), 4);  // lat 35.4796096°
  PutLe(p, 32, 1312000, 4), PutLe(p, 36, 1340000, 4);      // height, hMSL (mm)
  PutLe(p, 40, h_acc_mm, 4), PutLe(p, 44, 2 * h_acc_mm, 4);
  PutLe(p, 48, 1000, 4);  // velN 1 m/s
  PutLe(p, 68, s_acc_mm, 4);
  PutLe(p, 76, 120, 2);  // pDOP 1.2
  std::string f(100, '\0');
  f.resize(est::drivers::UbxDecoder::Encode(0x01, 0x07, p, f.data(), f.size()));
  return f;
}

std::string WithChecksum(const std::string& body) {
  unsigned char x = 0;
  for (const char c : body) x ^= static_cast<unsigned char>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", x);
  return "$" + body + tail;
}

// RMC and GGA quality 5 (RTK float) of the same epoch, 1 m/s north.
std::string NmeaFloat(int second) {
  char gga[128], rmc[128];
  std::snprintf(gga, sizeof gga,
                "GNGGA,0800%02d.00,3528.77658,N,05035.87859,E,5,12,0.80,1340.0,M,-28.0,M,1.0,0044",
                second);
  std::snprintf(rmc, sizeof rmc,
                "GNRMC,0800%02d.00,A,3528.77658,N,05035.87859,E,1.944,0.0,100626,,,R,V", second);
  return WithChecksum(rmc) + WithChecksum(gga);  // the F9P's order: RMC before GGA
}

struct LineRun {
  std::vector<est::GnssSample> samples;
  est::drivers::UbxDecoderStats ubx;
  est::drivers::NmeaDecoderStats nmea;
};

// Ten epochs at 1 Hz, each its NMEA then its NAV-PVT (hAcc 1 m), fed in 50-byte pieces.
LineRun ReadLine(const std::string& conf) {
  const est::NavdConfig cfg = est::NavdConfig::FromFile(est::ConfigFile::Parse(
      "[input]\ngnss_device = /nonexistent/ttyF9P\n" + conf +
          "[filter]\nnmea_rtk_fixed_std_m = 0.01\nnmea_rtk_float_std_m = 0.3\n",
      "navd.conf"));
  LineRun r;
  GnssReceivers rx(cfg, [&r](const est::GnssSample& g) { r.samples.push_back(g); });
  std::string line;
  for (int s = 10; s < 20; ++s) line += NmeaFloat(s) + NavPvtFloat(s, 1000, 50);
  for (std::size_t i = 0; i < line.size(); i += 50) rx.Feed(0, line.substr(i, 50));
  r.ubx = rx.ubx_stats();
  r.nmea = rx.nmea_stats();
  return r;
}

TEST(NavdNavPvtInput, FloatFixWeightedByItsHAccNotTheConfiguredSigma) {
  const LineRun r = ReadLine("");
  // one fix per epoch: the first GGA (before any NAV-PVT) and then the ten NAV-PVTs
  ASSERT_EQ(r.samples.size(), 11U);
  for (std::size_t i = 1; i < r.samples.size(); ++i) {
    const est::GnssSample& g = r.samples[i];
    EXPECT_EQ(g.fix_quality, 5);
    // 1.5 (ubx_acc_scale) × hAcc 1 m / √2 per axis; vertical 1.5 × vAcc 2 m held to the float
    // ceiling, 0.3 m (ubx_float_up_std_max_m)
    EXPECT_NEAR(g.pos_std_enu_m.x(), 1.5 / std::numbers::sqrt2, 1e-9);
    EXPECT_NEAR(g.pos_std_enu_m.z(), 0.3, 1e-9);
    EXPECT_NEAR(g.vel_std_enu_mps.x(), 0.075, 1e-9);  // 1.5 × sAcc 5 cm/s
    EXPECT_FALSE(g.vel_std_configured);
    EXPECT_NEAR(g.vel_enu_mps.y(), 1.0, 1e-9);
    EXPECT_NEAR(g.position.lat_deg, 35.4796096, 1e-9);
  }
  // epochs 1 s apart, on GPS time (UTC + 18 s)
  EXPECT_EQ(r.samples[2].t - r.samples[1].t, est::Nanoseconds(1'000'000'000));
  EXPECT_EQ(r.samples[1].t - r.samples[0].t, est::Nanoseconds(0)) << "GGA and NAV-PVT of 08:00:10";
  EXPECT_EQ(r.ubx.garbage_bytes, 0U);
  EXPECT_EQ(r.nmea.garbage_bytes, 0U);
  EXPECT_EQ(r.nmea.malformed, 0U);
  EXPECT_EQ(r.nmea.sentences_ok, 20U);
}

// a float fix's vAcc left unaided the height for the float's seconds and biased navd's roll for
// the fixed RTK after it (rtk_f9p_radio_loss): its vertical σ has a ceiling, configurable
TEST(NavdNavPvtInput, FloatFixVerticalSigmaHeldToItsConfiguredCeiling) {
  const LineRun wide = ReadLine("[filter]\nubx_float_up_std_max_m = 5\n");
  const LineRun tight = ReadLine("[filter]\nubx_float_up_std_max_m = 0.1\n");
  ASSERT_EQ(wide.samples.size(), 11U);
  ASSERT_EQ(tight.samples.size(), 11U);
  EXPECT_NEAR(wide.samples[5].pos_std_enu_m.z(), 3.0, 1e-9);  // 1.5 × vAcc 2 m, below 5 m
  EXPECT_NEAR(tight.samples[5].pos_std_enu_m.z(), 0.1, 1e-9);
  EXPECT_NEAR(tight.samples[5].pos_std_enu_m.x(), 1.5 / std::numbers::sqrt2, 1e-9);  // as before
}

TEST(NavdNavPvtInput, WithoutNavPvtTheGgaIsFusedAndTheUbxIsStillNoGarbage) {
  const LineRun r = ReadLine("gnss_nav_pvt = false\n");
  ASSERT_EQ(r.samples.size(), 10U);
  for (const est::GnssSample& g : r.samples) {
    EXPECT_EQ(g.fix_quality, 5);
    EXPECT_NEAR(g.pos_std_enu_m.x(), 0.3, 1e-9);  // nmea_rtk_float_std_m
  }
  EXPECT_EQ(r.ubx.garbage_bytes, 0U);
  EXPECT_EQ(r.nmea.garbage_bytes, 0U);
  EXPECT_EQ(r.ubx.frames_ok, 10U);
}

}  // namespace
}  // namespace hil::navd

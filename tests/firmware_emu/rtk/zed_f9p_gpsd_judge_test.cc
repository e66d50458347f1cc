// gpsd (gpsdecode 3.22, Debian package gpsd-clients) as the judge of the ZED-F9P rover's output:
// it decodes the rover's UBX NAV-PVT and NAV-RELPOSNED, and its NMEA 4.10 GGA, from a 20 s
// capture (the base 2 km away on the radio: standalone until 2 s, float until 12 s, then fixed).
// Checked: one TPV per NAV-PVT, mode 3 from the first fix on, gpsd's lat/lon/height those we
// encoded and, fixed, within 5 cm of the truth; status 1 (GPS) before the corrections and 2
// (DGPS: gpsd 3.22 reads diffSoln, not carrSoln, from NAV-PVT) after; RELPOSNED's baseline
// (relN/relE/relL) to the base; GGA's quality as gpsd's RTK statuses (4 float, 3 fixed) with
// the age of the corrections and the station id. Skips when gpsdecode is not installed.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gpsdecode_tpv.h"
#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

namespace fs = std::filesystem;
namespace key = gnss::ubx::f9key;

// gpsdecode -j over the bytes; its TPV reports.
std::string Capture(std::vector<std::pair<std::uint32_t, std::uint64_t>> flash) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.flash = std::move(flash);
  ZedF9pDevice dev(c, 3);
  std::string bytes;
  for (const SerialMessage& m : test::RunUntil(dev, TimeFromSeconds(20))) bytes += m.bytes;
  return bytes;
}

double Seconds(const nlohmann::json& tpv) {
  const std::string t = tpv.value("time", "");  // 2026-06-10T08:00:SS.sssZ
  return t.size() < 23 ? -1.0 : std::stod(t.substr(17, 6));
}

TEST(ZedF9pGpsdJudge, DecodesNavPvtAndRelposned) {
  if (!test::GpsdecodeInstalled()) GTEST_SKIP() << "gpsdecode not installed";
  const auto tpv = test::GpsdecodeTpv(
      Capture({{key::kNavPvtUart1, 1}, {key::kNavRelposnedUart1, 1}, {key::kUart1OutNmea, 0}}),
      "ubx");
  // gpsd reports a TPV per message and carries fields over: count seconds, not reports
  std::set<double> pvt, rel;
  for (const auto& j : tpv) {
    const double t = Seconds(j);
    pvt.insert(t);
    if (j.contains("relL")) {
      rel.insert(t);
      // the float's error; fixed from 12 s (gpsd may stamp the 11 s baseline with 12 s)
      const double tol_m = t < 13 ? 4.0 : 0.1;
      EXPECT_NEAR(j["relN"].get<double>(), -1600.0, tol_m) << t;
      EXPECT_NEAR(j["relE"].get<double>(), -1200.0, tol_m) << t;
      EXPECT_NEAR(j["relL"].get<double>(), 2000.0, tol_m) << t;
    }
    if (t < 1) {
      EXPECT_EQ(j.value("mode", -1), 1);  // no fix yet
      continue;
    }
    EXPECT_EQ(j.value("mode", -1), 3);
    EXPECT_EQ(j.value("status", 1), t < 2 ? 1 : 2) << j.dump();
    const double tol_deg = t < 2 ? 1e-4 : t < 12 ? 3e-5 : 5e-7;  // ≈ 10 m, 3 m, 5 cm
    EXPECT_NEAR(j["lat"].get<double>(), test::kRoverLat_deg, tol_deg) << t;
    EXPECT_NEAR(j["lon"].get<double>(), test::kRoverLon_deg, tol_deg) << t;
    if (t >= 12) {
      EXPECT_NEAR(j["altHAE"].get<double>(), test::kRoverHeight_m, 0.1);
      EXPECT_LT(j["eph"].get<double>(), 0.05);
    }
  }
  EXPECT_EQ(pvt.size(), 20U);
  EXPECT_EQ(rel.size(), 18U) << "RELPOSNED with a valid baseline from the float on (2 s … 19 s)";
}

TEST(ZedF9pGpsdJudge, DecodesGgaRtkQuality) {
  if (!test::GpsdecodeInstalled()) GTEST_SKIP() << "gpsdecode not installed";
  // RMC gives gpsd the date (GGA has the time of day only); GGA comes after it in an epoch
  const auto tpv = test::GpsdecodeTpv(Capture({{key::kNmeaVtgUart1, 0},
                                               {key::kNmeaGsaUart1, 0},
                                               {key::kNmeaGsvUart1, 0},
                                               {key::kNmeaGllUart1, 0}}),
                                      "gga");
  std::map<double, nlohmann::json> last;  // the epoch's last report: GGA's
  for (const auto& j : tpv) last[Seconds(j)] = j;
  std::set<double> seconds;
  for (const auto& [t, j] : last) {
    if (t < 1) continue;
    seconds.insert(t);
    // gpsd leaves out status 1 (GPS fix)
    EXPECT_EQ(j.value("status", 1), t < 2 ? 1 : t < 12 ? 4 : 3) << j.dump();
    if (t >= 2) {
      EXPECT_EQ(j.value("dgpsSta", -1), 1234);
      EXPECT_NEAR(j.value("dgpsAge", -1.0), 0.7, 0.2);
    }
  }
  EXPECT_EQ(seconds.size(), 19U);
}

}  // namespace
}  // namespace hil::rtk

// gpsd (gpsdecode 3.22, Debian package gpsd-clients) as the independent judge of the moving-base
// rover's NAV-RELPOSNED: a 30 s capture (NAV-PVT and NAV-RELPOSNED each epoch) of the dual-antenna
// rover (zed_f9p_moving_base_test's set: baseline 1.2 m, heading 30°), decoded by gpsdecode -j.
// Checked: gpsd's relN/relE/relD/relL/relH (its reading of relPosN/E/D/Length/Heading with their
// high-precision parts) agree with the truth of the baseline once fixed, and its count of
// RELPOSNED reports is that of the epochs with relPosValid. Skips when gpsdecode is missing.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
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

constexpr double kHeading_deg = 30.0, kBaseline_m = 1.2;

std::string Capture() {
  ZedF9pConfig c;
  c.start_utc = gnss::ParseIsoUtc("2026-06-10T08:00:00Z");
  c.model.p_BA_B_m = Eigen::Vector3d(1.0, 0.0, 2.8);
  MovingBaseConfig mb;
  mb.p_BA_B_m = Eigen::Vector3d(-0.2, 0.0, 2.8);
  c.moving_base = mb;
  c.flash = {{key::kNavRelposnedUart1, 1},
             {key::kNavPvtUart1, 1},
             {key::kUart1OutNmea, 0},
             {key::kUart2Baudrate, 460800}};
  ZedF9pDevice dev(c, 3);
  std::string bytes;
  DeviceOutput out;
  const double yaw_rad = (90.0 - kHeading_deg) * std::numbers::pi / 180.0;
  while (dev.next_event_time() < TimeFromSeconds(30)) {
    TruthSample s = test::StillTruth(dev.next_event_time());
    s.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
    dev.OnEvent(s, out);
    for (const auto& m : out.serial) bytes += m.bytes;
    out.clear();
  }
  return bytes;
}

TEST(ZedF9pMovingBaseGpsdJudge, DecodesTheBaselineAndItsHeading) {
  if (!test::GpsdecodeInstalled()) GTEST_SKIP() << "gpsdecode not installed";
  std::set<std::string> with_rel, fixed;
  for (const auto& j : test::GpsdecodeTpv(Capture(), "mb")) {
    if (!j.contains("relL")) continue;
    const std::string t = j.value("time", "");
    with_rel.insert(t);
    const double t_s = t.size() < 23 ? -1.0 : std::stod(t.substr(17, 6));
    if (t_s < 13) continue;  // fixed from 12 s (gpsd may stamp the 12 s baseline with 13 s)
    fixed.insert(t);
    EXPECT_NEAR(j["relL"].get<double>(), kBaseline_m, 0.05) << j.dump();
    EXPECT_NEAR(j["relN"].get<double>(),
                kBaseline_m * std::cos(kHeading_deg * std::numbers::pi / 180), 0.05);
    EXPECT_NEAR(j["relE"].get<double>(),
                kBaseline_m * std::sin(kHeading_deg * std::numbers::pi / 180), 0.05);
    EXPECT_NEAR(j["relD"].get<double>(), 0.0, 0.06);
    ASSERT_TRUE(j.contains("relH")) << j.dump();
    EXPECT_NEAR(std::remainder(j["relH"].get<double>() - kHeading_deg, 360.0), 0.0, 1.6)
        << j.dump();
  }
  EXPECT_EQ(with_rel.size(), 28U) << "relPosValid from 2 s to 29 s";
  EXPECT_EQ(fixed.size(), 17U);
}

}  // namespace
}  // namespace hil::rtk

// The ZED-F9P as the rover of a moving base (dual-antenna heading): a second F9P 1.2 m behind it
// on the vehicle sends 4072.0 and MSM7 down a 460800 Bd wire into UART2. NAV-RELPOSNED is read
// here by its byte layout in the interface description (UBX-18010854: version U1 at 0,
// refStationId U2 at 2, iTOW U4 at 4, relPosN/E/D I4 at 8/12/16 cm, relPosLength I4 at 20 cm,
// relPosHeading I4 at 24 1e-5 deg, relPosHPN/E/D/Length I1 at 32–35 0.1 mm, accN/E/D/Length U4
// at 36–48 0.1 mm, accHeading U4 at 52 1e-5 deg, flags X4 at 60), not through the encoder.
// The golden vectors/gnss/zed_f9p_moving_base_relposned.golden holds the stream of the first
// 14 s (HIL_REGEN_VECTORS=1 rewrites it).
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_frame.h"

#include "golden_file.h"
#include "ubx_le_field.h"
#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;
using test::Le;

constexpr double kDeg = std::numbers::pi / 180.0;

// NAV-RELPOSNED version 1 as the interface description lays it out.
struct Relposned {
  double t_s = 0;
  int version = 0, ref_station = 0;
  double n_m = 0, e_m = 0, d_m = 0, length_m = 0, heading_deg = 0;
  double acc_length_m = 0, acc_heading_deg = 0;
  bool fix_ok = false, diff = false, rel_valid = false, moving = false;
  bool ref_pos_miss = false, ref_obs_miss = false, heading_valid = false;
  int carr = 0;
};

Relposned Parse(double t_s, std::string_view frame) {
  EXPECT_EQ(frame.size(), 6U + 64U + 2U);
  const std::string_view p = frame.substr(6, 64);
  Relposned r;
  r.t_s = t_s;
  r.version = static_cast<int>(Le(p, 0, 1, false));
  r.ref_station = static_cast<int>(Le(p, 2, 2, false));
  const auto cm = [&](std::size_t off, std::size_t hp) {
    return static_cast<double>(Le(p, off, 4, true)) * 1e-2 +
           static_cast<double>(Le(p, hp, 1, true)) * 1e-4;
  };
  r.n_m = cm(8, 32), r.e_m = cm(12, 33), r.d_m = cm(16, 34), r.length_m = cm(20, 35);
  r.heading_deg = static_cast<double>(Le(p, 24, 4, true)) * 1e-5;
  r.acc_length_m = static_cast<double>(Le(p, 48, 4, false)) * 1e-4;
  r.acc_heading_deg = static_cast<double>(Le(p, 52, 4, false)) * 1e-5;
  const auto flags = static_cast<std::uint32_t>(Le(p, 60, 4, false));
  r.fix_ok = (flags & 1U) != 0, r.diff = (flags >> 1 & 1U) != 0;
  r.rel_valid = (flags >> 2 & 1U) != 0, r.carr = static_cast<int>(flags >> 3 & 3U);
  r.moving = (flags >> 5 & 1U) != 0, r.ref_pos_miss = (flags >> 6 & 1U) != 0;
  r.ref_obs_miss = (flags >> 7 & 1U) != 0, r.heading_valid = (flags >> 8 & 1U) != 0;
  return r;
}

// The vehicle's heading (clockwise from north) at t; the two antennas on its roof.
using HeadingOf = std::function<double(double t_s)>;

ZedF9pConfig DualAntennaRover(int wire_baud = 460800) {
  ZedF9pConfig c;
  c.start_utc = gnss::ParseIsoUtc("2026-06-10T08:00:00Z");
  c.model.p_BA_B_m = Eigen::Vector3d(1.0, 0.0, 2.8);  // rover antenna: 1.2 m ahead of the base's
  MovingBaseConfig mb;
  mb.p_BA_B_m = Eigen::Vector3d(-0.2, 0.0, 2.8);
  mb.baud = wire_baud;
  c.moving_base = mb;
  c.flash = {{key::kNavRelposnedUart1, 1},
             {key::kNavPvtUart1, 1},
             {key::kUart1OutNmea, 0},
             {key::kUart1Baudrate, 115200},
             {key::kUart2Baudrate, static_cast<std::uint64_t>(wire_baud)}};
  return c;
}

std::vector<SerialMessage> RunTurning(ZedF9pDevice& dev, double end_s, const HeadingOf& heading) {
  std::vector<SerialMessage> sent;
  DeviceOutput out;
  while (dev.next_event_time() < TimeFromSeconds(end_s)) {
    TruthSample s = test::StillTruth(dev.next_event_time());
    // body FLU → ENU: the forward axis turned from east by 90° − heading (counter-clockwise)
    const double yaw_rad = (90.0 - heading(ToSeconds(s.t - Time{}))) * kDeg;
    s.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
    dev.OnEvent(s, out);
    for (auto& m : out.serial) sent.push_back(std::move(m));
    out.clear();
  }
  return sent;
}

std::vector<Relposned> RelposnedOf(const std::vector<SerialMessage>& sent) {
  std::vector<Relposned> r;
  for (const SerialMessage& m : sent) {
    if (m.name == "UBX-NAV-RELPOSNED") r.push_back(Parse(ToSeconds(m.t_ready - Time{}), m.bytes));
  }
  return r;
}

double AngleDiff_deg(double a, double b) { return std::remainder(a - b, 360.0); }

TEST(ZedF9pMovingBase, RelposnedGivesTheHeadingOfTheBaseline) {
  ZedF9pDevice dev(DualAntennaRover(), 3);
  const auto rel = RelposnedOf(RunTurning(dev, 30, [](double) { return 30.0; }));
  ASSERT_EQ(rel.size(), 30U);
  for (const Relposned& r : rel) {
    SCOPED_TRACE(r.t_s);
    EXPECT_EQ(r.version, 1);
    EXPECT_TRUE(r.moving) << "isMoving in every epoch of a moving-base rover";
    if (r.t_s < 1) continue;  // hot start: no fix in the first epoch
    EXPECT_TRUE(r.fix_ok);
    // corrections from 0.04 s: float from 2 s, fixed 10 s later (RoverRtk's defaults)
    EXPECT_EQ(r.carr, r.t_s < 2 ? 0 : r.t_s < 12 ? 1 : 2);
    EXPECT_EQ(r.diff, r.t_s >= 2);
    EXPECT_EQ(r.rel_valid, r.t_s >= 2);
    EXPECT_FALSE(r.ref_obs_miss) << "the MSM's last byte is in 37 ms after the epoch";
    EXPECT_FALSE(r.ref_pos_miss);
    if (r.t_s < 2) {
      EXPECT_EQ(r.heading_deg, 0.0);
      continue;
    }
    EXPECT_EQ(r.ref_station, 0);
    if (r.carr == 2) {
      // fixed: σ per axis (0.01 m + 1.2 µm) / 1.1774 → accHeading atan(σ / 1.2 m) = 0.406°
      EXPECT_NEAR(r.acc_heading_deg, 0.4056, 0.01);  // over the measured length
      EXPECT_TRUE(r.heading_valid);
      EXPECT_NEAR(AngleDiff_deg(r.heading_deg, 30.0), 0.0, 4 * r.acc_heading_deg);
      EXPECT_NEAR(r.length_m, 1.2, 0.05);
      EXPECT_NEAR(r.n_m, 1.2 * std::cos(30 * kDeg), 0.05);
      EXPECT_NEAR(r.e_m, 1.2 * std::sin(30 * kDeg), 0.05);
      EXPECT_NEAR(r.d_m, 0.0, 0.06);
    } else {
      // float: σ converges from 1 m (20 s time constant): heading valid only below 5°
      EXPECT_EQ(r.heading_valid, r.acc_heading_deg <= 5.0);
      EXPECT_GT(r.acc_heading_deg, 5.0) << "float σ ≥ 0.6 m over its first 10 s";
    }
  }
}

TEST(ZedF9pMovingBase, HeadingFollowsATurningVehicle) {
  ZedF9pDevice dev(DualAntennaRover(), 5);
  const auto turn = [](double t_s) { return std::fmod(10.0 * t_s, 360.0); };  // 10°/s
  int checked = 0;
  for (const Relposned& r : RelposnedOf(RunTurning(dev, 60, turn))) {
    if (r.carr != 2) continue;
    // the epoch's heading at the epoch's time (its output comes 50 ms later)
    const double truth_deg = turn(std::round(r.t_s - 0.05));
    EXPECT_NEAR(AngleDiff_deg(r.heading_deg, truth_deg), 0.0, 4 * r.acc_heading_deg) << r.t_s;
    EXPECT_TRUE(r.heading_valid);
    ++checked;
  }
  EXPECT_EQ(checked, 48) << "fixed from 12 s to 59 s";
}

TEST(ZedF9pMovingBase, StatisticsMeasureTheHeadingAgainstTheTruth) {
  ZedF9pDevice dev(DualAntennaRover(), 3);
  const auto rel = RelposnedOf(RunTurning(dev, 30, [](double) { return 30.0; }));
  const ZedF9pStatistics& s = dev.rover_statistics();
  int valid = 0;
  double sum_sq = 0;
  for (const Relposned& r : rel) {
    if (!r.heading_valid) continue;
    ++valid;
    sum_sq += std::pow(AngleDiff_deg(r.heading_deg, 30.0), 2);
  }
  EXPECT_EQ(s.heading_valid_epochs, static_cast<std::uint64_t>(valid));
  EXPECT_EQ(valid, 18) << "fixed 12 s … 29 s";
  // the statistics against the message's heading (1e-5° steps)
  EXPECT_NEAR(std::sqrt(s.heading_error_sum_sq_deg2 / valid), std::sqrt(sum_sq / valid), 1e-4);
  EXPECT_NEAR(s.acc_heading_sum_deg / valid, 0.4056, 0.01);
}

TEST(ZedF9pMovingBase, SlowWireMissesTheTimeMatchedObservations) {
  // at 38400 Bd the epoch's ~300 bytes take ~80 ms, after the rover's 50 ms output
  ZedF9pDevice dev(DualAntennaRover(38400), 3);
  const auto rel = RelposnedOf(RunTurning(dev, 20, [](double) { return 30.0; }));
  ASSERT_EQ(rel.size(), 20U);
  for (const Relposned& r : rel) {
    if (r.t_s < 1) continue;
    EXPECT_TRUE(r.ref_obs_miss) << r.t_s;
    EXPECT_TRUE(r.ref_pos_miss) << r.t_s;
    EXPECT_FALSE(r.rel_valid) << r.t_s;
    EXPECT_FALSE(r.heading_valid) << r.t_s;
    EXPECT_EQ(r.carr, r.t_s < 2 ? 0 : r.t_s < 12 ? 1 : 2) << "the corrections still arrive";
  }
}

TEST(ZedF9pMovingBase, AbsoluteSolutionStaysStandalone) {
  ZedF9pDevice dev(DualAntennaRover(), 3);
  int pvt = 0;
  for (const SerialMessage& m : RunTurning(dev, 20, [](double) { return 30.0; })) {
    if (m.name != "UBX-NAV-PVT") continue;
    const std::string_view p = std::string_view(m.bytes).substr(6, 92);
    EXPECT_EQ(Le(p, 21, 1, false) >> 6, 0) << "carrSoln";
    EXPECT_EQ(Le(p, 21, 1, false) >> 1 & 1, 0) << "diffSoln";
    ++pvt;
  }
  EXPECT_EQ(pvt, 20);
  EXPECT_EQ(dev.timeline().size(), 3U) << "none, float, fixed: the baseline's carrSoln";
}

TEST(ZedF9pMovingBase, UartTwoAtAnotherRateDecodesNothing) {
  ZedF9pConfig c = DualAntennaRover();
  c.flash.back().second = 38400;  // CFG-UART2-BAUDRATE left at the default
  ZedF9pDevice dev(c, 3);
  for (const Relposned& r : RelposnedOf(RunTurning(dev, 15, [](double) { return 30.0; }))) {
    EXPECT_EQ(r.carr, 0) << r.t_s;
    EXPECT_TRUE(r.ref_pos_miss) << "no 4072.0 received";
    EXPECT_FALSE(r.rel_valid);
  }
}

std::string Line(const Relposned& r) {
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "  N=%.4f E=%.4f D=%.4f L=%.4f heading=%.5f accL=%.4f accHeading=%.5f "
                "fixOK=%d diff=%d relValid=%d carr=%d moving=%d refPosMiss=%d refObsMiss=%d "
                "headingValid=%d\n",
                r.n_m, r.e_m, r.d_m, r.length_m, r.heading_deg, r.acc_length_m, r.acc_heading_deg,
                r.fix_ok, r.diff, r.rel_valid, r.carr, r.moving, r.ref_pos_miss, r.ref_obs_miss,
                r.heading_valid);
  return buf;
}

TEST(ZedF9pMovingBase, GoldenRelposnedStream) {
  ZedF9pDevice dev(DualAntennaRover(), 3);
  std::ostringstream g;
  g << "# ZED-F9P moving-base rover, heading 30 deg, baseline 1.2 m, first 14 s: NAV-RELPOSNED\n"
       "# (tests/firmware_emu/rtk/zed_f9p_moving_base_test.cc; HIL_REGEN_VECTORS=1 rewrites it).\n"
       "# Per message: t_ready in ms, hex frame, then the fields read by the spec's offsets.\n";
  for (const SerialMessage& m : RunTurning(dev, 14, [](double) { return 30.0; })) {
    if (m.name != "UBX-NAV-RELPOSNED") continue;
    g << ToNs(m.t_ready) / 1000000 << " ";
    char hex[3];
    for (const char c : m.bytes) {
      std::snprintf(hex, sizeof hex, "%02x", static_cast<unsigned char>(c));
      g << hex;
    }
    g << "\n" << Line(Parse(ToSeconds(m.t_ready - Time{}), m.bytes));
  }
  hil::test::CheckOrWriteGolden("vectors/gnss/zed_f9p_moving_base_relposned.golden", g.str());
}

TEST(ZedF9pMovingBase, SameSeedSameBytes) {
  ZedF9pDevice a(DualAntennaRover(), 9), b(DualAntennaRover(), 9);
  const HeadingOf h = [](double t_s) { return 5.0 * t_s; };
  std::string x, y;
  for (const auto& m : RunTurning(a, 20, h)) x += m.bytes;
  for (const auto& m : RunTurning(b, 20, h)) y += m.bytes;
  EXPECT_EQ(x, y);
  EXPECT_GT(x.size(), 2000U);
}

}  // namespace
}  // namespace hil::rtk

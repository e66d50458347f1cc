// The ZED-F9P rover's RTK state follows its corrections: without them a standalone 3-D fix
// (carrSoln 0); when the base's radio stream arrives, float after time_to_float_s and fixed
// time_to_fix_s later; a 30 s radio cut: float once the age of the corrections passes
// fixed_max_age_s, 3-D once it passes CFG-NAVSPG-CONSTR_DGNSSTO (set to 20 s here by VALSET in
// Flash); corrections back: float, then fixed again. Also: RXM-RTCM for every frame received,
// RELPOSNED's baseline to the base, and a corrupted frame counted as crcFailed.
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/rtk/rover_rtk.h"

#include "zed_f9p_fixture.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;
using gnss::ubx::CarrSoln;

// The time of the first transition to `c` at or after `from` (nullopt: none).
std::optional<double> FirstTo(const std::vector<RtkTransition>& tl, CarrSoln c, double from) {
  for (const RtkTransition& r : tl) {
    if (r.carr_soln == c && ToSeconds(r.t - Time{}) >= from) return ToSeconds(r.t - Time{});
  }
  return std::nullopt;
}

TEST(ZedF9pTimeline, CorrectionsStartCutAndReturn) {
  ZedF9pConfig c = test::RoverWithRadio({{TimeFromSeconds(60), TimeFromSeconds(90)}});
  c.flash = {{key::kNavspgConstrDgnssTo, 20}, {key::kNavPvtUart1, 1}, {key::kRxmRtcmUart1, 1}};
  ZedF9pDevice dev(c, 3);
  test::RunUntil(dev, TimeFromSeconds(120));
  const auto& tl = dev.timeline();
  ASSERT_FALSE(tl.empty());
  EXPECT_EQ(tl.front().carr_soln, CarrSoln::kNone);
  // the first frames arrive ≈ 0.6 s after the base's epoch 0 (30 ms lag, 0.4 s on air at
  // 960 B/s, 50 ms latency, 0.1 s down the 38400 Bd line): float at the first epoch ≥ 1.6 s
  const auto t_float = FirstTo(tl, CarrSoln::kFloat, 0);
  const auto t_fixed = FirstTo(tl, CarrSoln::kFixed, 0);
  ASSERT_TRUE(t_float && t_fixed);
  EXPECT_DOUBLE_EQ(*t_float, 2.0);
  EXPECT_DOUBLE_EQ(*t_fixed, *t_float + c.rtk.time_to_fix_s);
  // the cut: the last packet sent at 59 s arrives ≈ 59.6 s; age > 5 s at 65 s, > 20 s at 80 s
  const auto t_cut_float = FirstTo(tl, CarrSoln::kFloat, 60);
  const auto t_cut_none = FirstTo(tl, CarrSoln::kNone, 60);
  ASSERT_TRUE(t_cut_float && t_cut_none);
  EXPECT_DOUBLE_EQ(*t_cut_float, 65.0);
  EXPECT_DOUBLE_EQ(*t_cut_none, 80.0);
  // back at 90 s: float at 92 s, fixed 10 s later
  const auto t_back_float = FirstTo(tl, CarrSoln::kFloat, 81);
  const auto t_back_fixed = FirstTo(tl, CarrSoln::kFixed, 81);
  ASSERT_TRUE(t_back_float && t_back_fixed);
  EXPECT_DOUBLE_EQ(*t_back_float, 92.0);
  EXPECT_DOUBLE_EQ(*t_back_fixed, 102.0);
  EXPECT_EQ(tl.size(), 7U);  // none, float, fixed, float, none, float, fixed
  // 120 epochs; fixed 2..64 → 53 s… the counts follow the timeline
  EXPECT_EQ(dev.rover_statistics().epochs, 120U);
  EXPECT_EQ(dev.rover_statistics().epochs_fixed, (65U - 12U) + (120U - 102U));
  EXPECT_EQ(dev.rover_statistics().rtcm_crc_failed, 0U);
}

TEST(ZedF9pTimeline, FloatOnlyModeNeverFixes) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.flash = {{key::kNavhpgDgnssMode, 2}};
  ZedF9pDevice dev(c, 3);
  test::RunUntil(dev, TimeFromSeconds(40));
  EXPECT_FALSE(FirstTo(dev.timeline(), CarrSoln::kFixed, 0));
  EXPECT_TRUE(FirstTo(dev.timeline(), CarrSoln::kFloat, 0));
}

TEST(ZedF9pTimeline, NoCorrectionsStaysStandalone) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.radio_base.reset();
  ZedF9pDevice dev(c, 3);
  test::RunUntil(dev, TimeFromSeconds(30));
  ASSERT_EQ(dev.timeline().size(), 1U);
  EXPECT_EQ(dev.last_epoch().carr_soln, CarrSoln::kNone);
  EXPECT_EQ(dev.last_fix().fix_type, gnss::FixType::k3D);
  EXPECT_GT(dev.last_fix().h_acc_m, 0.5) << "a standalone fix reports metres";
}

TEST(ZedF9pTimeline, SkyOutageThenReconvergence) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.sky_outages = {{TimeFromSeconds(30), TimeFromSeconds(40)}};
  ZedF9pDevice dev(c, 3);
  test::RunUntil(dev, TimeFromSeconds(45));
  const auto tl = dev.timeline();
  // fixed at 12 s; no fix 30-40 s (carrSoln 0); the fix back after re-acquisition (1 s): float at
  // once (the corrections kept flowing), fixed time_to_fix_s later
  ASSERT_EQ(tl.size(), 5U);
  EXPECT_EQ(tl[3].carr_soln, CarrSoln::kNone);
  EXPECT_DOUBLE_EQ(ToSeconds(tl[3].t - Time{}), 30.0);
  EXPECT_EQ(tl[4].carr_soln, CarrSoln::kFloat);
  const double t_back = ToSeconds(tl[4].t - Time{});
  EXPECT_GE(t_back, 40.0);
  EXPECT_LE(t_back, 42.0);
  EXPECT_EQ(dev.last_epoch().carr_soln, CarrSoln::kFloat) << "fixed only 10 s after " << t_back;
  test::RunUntil(dev, TimeFromSeconds(t_back + 10.5));
  EXPECT_EQ(dev.timeline().back().carr_soln, CarrSoln::kFixed);
  EXPECT_DOUBLE_EQ(ToSeconds(dev.timeline().back().t - Time{}), t_back + 10.0);
}

TEST(ZedF9pTimeline, Uart2AtAnotherBaudDecodesNothing) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.flash = {{key::kUart2Baudrate, 115200}};  // the radio modem's line is 38400 Bd
  ZedF9pDevice dev(c, 3);
  test::RunUntil(dev, TimeFromSeconds(20));
  EXPECT_EQ(dev.rover_statistics().rtcm_frames, 0U);
  EXPECT_EQ(dev.timeline().size(), 1U);
}

TEST(ZedF9pTimeline, FixedAccuracyGrowsWithTheBaseline) {
  RoverRtkConfig c;
  RoverRtk near(c, 1), far(c, 1);
  RoverRtkEpoch en, ef;
  for (int k = 1; k <= 30; ++k) {
    near.OnCorrection(TimeFromSeconds(k - 0.5));
    far.OnCorrection(TimeFromSeconds(k - 0.5));
    en = near.Step(TimeFromSeconds(k), 1.0, true, 2e3);
    ef = far.Step(TimeFromSeconds(k), 1.0, true, 20e3);
  }
  ASSERT_EQ(en.state, gnss::RtkState::kFixed);
  // CEP 0.01 m + 1 ppm: 12 mm at 2 km, 30 mm at 20 km (per-axis sigma = CEP / 1.1774)
  EXPECT_NEAR(en.sigma_h_m * 1.1774, 0.012, 1e-6);
  EXPECT_NEAR(ef.sigma_h_m * 1.1774, 0.030, 1e-6);
}

TEST(ZedF9pTimeline, TimeToFixGrowsWithTheBaselineWhenConfigured) {
  RoverRtkConfig c;
  c.time_to_fix_per_km_s = 1.0;
  RoverRtk near(c, 1), far(c, 1);
  std::optional<int> fixed_near, fixed_far;
  for (int k = 1; k <= 60; ++k) {
    near.OnCorrection(TimeFromSeconds(k - 0.5));
    far.OnCorrection(TimeFromSeconds(k - 0.5));
    if (near.Step(TimeFromSeconds(k), 1.0, true, 2e3).state == gnss::RtkState::kFixed &&
        !fixed_near)
      fixed_near = k;
    if (far.Step(TimeFromSeconds(k), 1.0, true, 20e3).state == gnss::RtkState::kFixed && !fixed_far)
      fixed_far = k;
  }
  // float at 2 s (1 s after the first correction at 0.5 s, on the epoch grid); then 10 s + 1 s/km
  ASSERT_TRUE(fixed_near && fixed_far);
  EXPECT_EQ(*fixed_near, 2 + 12);
  EXPECT_EQ(*fixed_far, 2 + 30);
}

TEST(ZedF9pTimeline, RxmRtcmAndRelposned) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.flash = {{key::kRxmRtcmUart1, 1}, {key::kNavRelposnedUart1, 1}, {key::kUart1OutNmea, 0}};
  ZedF9pDevice dev(c, 3);
  const auto sent = test::RunUntil(dev, TimeFromSeconds(20));
  int rxm = 0, msm = 0, station = 0;
  for (const SerialMessage& m : sent) {
    if (m.name != "UBX-RXM-RTCM") continue;
    const gnss::ubx::FrameAt f = gnss::ubx::ParseFrameAt(m.bytes);
    ASSERT_EQ(f.status, gnss::ubx::FrameAtStatus::kFrame);
    ++rxm;
    const int type =
        static_cast<unsigned char>(f.payload[6]) | static_cast<unsigned char>(f.payload[7]) << 8;
    EXPECT_EQ(static_cast<unsigned char>(f.payload[1]) & 1, 0) << "crcFailed";
    EXPECT_EQ(static_cast<unsigned char>(f.payload[1]) >> 1 & 3, 2) << "msgUsed";
    msm += type == 1077;
    station += type == 1006;
  }
  EXPECT_EQ(msm, 20);     // one MSM7 a second
  EXPECT_EQ(station, 2);  // 1006 every 10 s
  EXPECT_EQ(rxm, msm + station);
  const Eigen::Vector3d rel = dev.last_epoch().rel_pos_NED_m;
  EXPECT_NEAR(rel.x(), -1600.0, 0.5);  // the rover is south-west of its base
  EXPECT_NEAR(rel.y(), -1200.0, 0.5);
  EXPECT_TRUE(dev.last_epoch().relpos_valid);
}

TEST(ZedF9pTimeline, CorruptedFrameIsCrcFailed) {
  ZedF9pConfig c = test::RoverWithRadio();
  c.radio_base.reset();
  c.flash = {{key::kRxmRtcmUart1, 1}, {key::kUart1OutNmea, 0}};
  ZedF9pDevice dev(c, 3);
  std::string stream = test::BaseStream(test::KarajBase(rtcm3::MsmKind::kMsm4), 2, 7);
  stream[10] = static_cast<char>(stream[10] ^ 0x40);  // a bit flipped in the first frame (1006)
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.2), stream, out);  // an NTRIP client writing to UART1
  const auto sent = test::RunUntil(dev, TimeFromSeconds(3));
  EXPECT_EQ(dev.rover_statistics().rtcm_crc_failed, 1U);
  EXPECT_EQ(dev.rover_statistics().rtcm_frames, 3U);  // 1006 (failed), 1074, 1074
  int failed = 0;
  for (const SerialMessage& m : sent) {
    if (m.name == "UBX-RXM-RTCM") failed += static_cast<unsigned char>(m.bytes[7]) & 1;
  }
  EXPECT_EQ(failed, 1);
}

}  // namespace
}  // namespace hil::rtk

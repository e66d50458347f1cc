// Navigator behaviours that do not need the simulator: the seed-000 three-receiver mode, late and
// out-of-order inputs, bad input.
#include "hil/estimator/navigator.h"

#include <chrono>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "hil/estimator/drivers/ubx_nav_pvt_sample.h"

namespace hil::estimator {
namespace {

using namespace std::chrono_literals;

constexpr GpsTime kT0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);

TEST(NavigatorTest, ThreeReceiversGiveCentreAndHeading) {
  // GIVEN seed 000's three antennas on a 3 m circle, 120° apart
  NavigatorParams p;
  p.mode = NavMode::kMultiGnss;
  for (int i = 0; i < 3; ++i) {
    const double a = i * 2 * M_PI / 3;
    p.multi_antenna_B_m.col(i) = Eigen::Vector3d(3 * std::cos(a), 3 * std::sin(a), 0);
  }
  Navigator nav(p);
  const LocalTangentFrame frame({35.4796096, 50.5979765, 1300});
  const Eigen::Vector3d centre(12.0, -7.0, 0.0);
  const double yaw = 0.4;  // counter-clockwise from east
  // WHEN the three fixes of one epoch arrive (in any order)
  for (int i : {2, 0, 1}) {
    GnssSample g;
    g.t = kT0;
    g.antenna = i;
    g.position = frame.ToLla(centre + Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                          p.multi_antenna_B_m.col(i));
    g.pos_std_enu_m.setConstant(0.3);
    nav.Push(g);
  }
  // THEN the solution is the circle's centre with the body heading
  const NavOutput o = nav.Output();
  ASSERT_TRUE(o.valid);
  const Eigen::Vector3d c = frame.ToLocal(o.position);
  EXPECT_LT((c - centre).head<2>().norm(), 1e-6);
  const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(x.y(), x.x()), yaw,
              1e-5);  // (the navigator anchors its own tangent plane at the first fix)
}

TEST(NavigatorTest, CountsOutOfOrderImuAndRejectsBadInput) {
  Navigator nav(NavigatorParams{});
  ImuSample s;
  s.t = kT0;
  s.dt_s = 0.01;
  nav.Push(s);
  nav.Push(s);  // same time again
  s.dt_s = std::nan("");
  s.t += 10ms;
  nav.Push(s);
  GnssSample g;
  g.position.lat_deg = 123.0;  // impossible latitude
  nav.Push(g);
  EXPECT_EQ(nav.stats().imu_samples, 1u);
  EXPECT_EQ(nav.stats().imu_out_of_order, 1u);
  EXPECT_EQ(nav.stats().bad_input, 2u);
  EXPECT_TRUE(nav.status() & kStatusBadInput);
  EXPECT_FALSE(nav.aligned());
}

// An aligned EKF navigator driven at 100 Hz, level and still but for a GNSS course of 1 m/s north.
struct WaitRig {
  explicit WaitRig(Nanoseconds max_latency) : nav(Params(max_latency)) {}
  static NavigatorParams Params(Nanoseconds max_latency) {
    NavigatorParams p;
    p.mode = NavMode::kEkf;
    p.fusion_horizon = 200ms;
    p.gnss_max_latency = max_latency;
    return p;
  }
  void ImuUntil(GpsTime t_end) {
    for (; t_imu < t_end; t_imu += 10ms) {
      ImuSample s;
      s.t = t_imu + 10ms;
      s.dt_s = 0.01;
      s.delta_velocity_B_mps = Eigen::Vector3d(0, 0, 9.80) * 0.01;
      nav.Push(s);
      nav.Update();
    }
  }
  void Fix(GpsTime t) {
    GnssSample g;
    g.t = t;
    g.position = frame.ToLla(Eigen::Vector3d(0, 1e-9 * static_cast<double>((t - kT0).count()), 0));
    g.pos_std_enu_m.setConstant(0.1);
    g.has_velocity = true;
    g.vel_enu_mps = Eigen::Vector3d(0, 1, 0);
    nav.Push(g);
  }
  Navigator nav;
  LocalTangentFrame frame{Lla{45.0, 10.0, 100.0}};
  GpsTime t_imu = kT0;
};

TEST(NavigatorTest, WaitsForADueFixUpToTheMaximumLatency) {
  for (const bool wait : {true, false}) {
    // GIVEN an aligned filter with fixes at 1 Hz, fused on time
    WaitRig rig(wait ? 2500ms : 0ms);
    for (int k = 0; k < 3; ++k) {
      rig.ImuUntil(kT0 + k * 1s + 100ms);
      rig.Fix(kT0 + k * 1s);
    }
    ASSERT_TRUE(rig.nav.aligned());
    ASSERT_EQ(rig.nav.stats().gnss_late, 0u);
    // WHEN the next fix (due at 3 s) reaches the host 1.5 s after its epoch (a slow link, a busy
    // host)
    rig.ImuUntil(kT0 + 4500ms);
    rig.Fix(kT0 + 3s);
    rig.ImuUntil(kT0 + 4600ms);
    // THEN with a 2.5 s wait the filter held at the due epoch and fuses it; with no wait it is late
    EXPECT_EQ(rig.nav.stats().gnss_late, wait ? 0u : 1u);
    if (wait) {
      EXPECT_GE(rig.nav.filter_time(), kT0 + 3s);
    }
    // AND the output always reports the newest IMU time (the output predictor)
    EXPECT_EQ(rig.nav.Output().t, kT0 + 4600ms);
  }
  // AND without fixes (an outage) the waiting filter waits the maximum latency for the due fix,
  // then runs at the horizon again (its output predictor does not carry the free INS over the
  // whole wait)
  WaitRig rig(2500ms);
  for (int k = 0; k < 3; ++k) {
    rig.ImuUntil(kT0 + k * 1s + 100ms);
    rig.Fix(kT0 + k * 1s);
  }
  rig.ImuUntil(kT0 + 5s);
  EXPECT_NEAR(static_cast<double>((kT0 + 5s - rig.nav.filter_time()).count()) * 1e-9, 2.0, 0.011);
  rig.ImuUntil(kT0 + 20s);
  EXPECT_NEAR(static_cast<double>((kT0 + 20s - rig.nav.filter_time()).count()) * 1e-9, 0.2, 0.011);
}

// A level vehicle driving east at 1 m/s with the EKF (IMU 100 Hz, GNSS 1 Hz): its antenna's fixes
// with the given white σ, at the body point plus the configured lever arm.
struct EastboundRig {
  EastboundRig(const NavigatorParams& p, const Eigen::Vector3d& white_std_m)
      : nav(p), lever_arm_B_m(p.ekf.lever_arm_B_m), fix_std_m(white_std_m) {}
  void Fix(GpsTime t) {
    GnssSample g;
    g.t = t;
    const double x_m = static_cast<double>((t - kT0).count()) * 1e-9;
    g.position = frame.ToLla(Eigen::Vector3d(x_m, 0, 0) + lever_arm_B_m);
    g.pos_std_enu_m = fix_std_m;
    g.has_velocity = true;
    g.vel_enu_mps = Eigen::Vector3d(1, 0, 0);
    g.vel_std_enu_mps = Eigen::Vector3d::Constant(0.05);
    nav.Push(g);
  }
  void Imu(GpsTime t) {
    ImuSample s;
    s.t = t;
    s.dt_s = 0.01;
    s.delta_velocity_B_mps = Eigen::Vector3d(0, 0, g0 * 0.01);
    nav.Push(s);
    nav.Update();
  }
  // IMU samples every 10 ms in (from, to], a fix every whole second
  void Drive(GpsTime from, GpsTime to) {
    for (GpsTime t = from + 10ms; t <= to; t += 10ms) {
      Imu(t);
      if ((t - kT0) % 1s == 0ns) Fix(t);
    }
  }
  Navigator nav;
  Eigen::Vector3d lever_arm_B_m, fix_std_m;
  const LocalTangentFrame frame{{48.0, 11.0, 500.0}};
  const double g0 = NormalGravity(48.0, 500.0);
};

// issue 39: the fallback solution is the body point, as the filter's, and its σ holds the
// receiver's correlated error (faults/mcu_reset: the antenna 0.84 m ahead reported at σ 4 cm)
TEST(NavigatorTest, TheFallbackWhileTheImuIsSilentIsTheBodyPointWithTheReceiversError) {
  // GIVEN an aligned EKF, its antenna 1 m ahead of the body point and 0.5 m up, its receiver's
  // correlated error modelled at 0.25 m, on a level vehicle driving east at 1 m/s
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.ekf.lever_arm_B_m = Eigen::Vector3d(1.0, 0.0, 0.5);
  p.ekf.gnss_error_tau_s = 5.0;
  p.ekf.gnss_error_std_m = 0.25;
  EastboundRig rig(p, Eigen::Vector3d(0.04, 0.04, 0.08));
  rig.Drive(kT0, kT0 + 10s);
  ASSERT_TRUE(rig.nav.aligned());
  // WHEN the IMU falls silent while the fixes keep coming
  for (int k = 11; k <= 15; ++k) rig.Fix(kT0 + k * 1s);
  ASSERT_TRUE(rig.nav.ImuLost());
  const NavOutput lost = rig.nav.Output();
  // THEN the solution is the body point under the fix, not the antenna
  EXPECT_NEAR(rig.frame.ToLocal(lost.position).x(), 15.0, 0.05);
  EXPECT_NEAR(rig.frame.ToLocal(lost.position).z(), 0.0, 0.05);
  // AND its σ is the fix's white σ with the receiver's correlated error
  EXPECT_GT(lost.pos_std_enu_m.x(), 0.24);
  EXPECT_GT(lost.pos_std_enu_m.y(), 0.24);
}

TEST(NavigatorTest, FallsBackToTheFixesWhileTheImuIsSilentAndRestartsAfter) {
  // GIVEN an aligned EKF on a level vehicle driving east at 1 m/s (IMU 100 Hz, GNSS 1 Hz)
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  EastboundRig rig(p, Eigen::Vector3d(0.3, 0.3, 0.6));
  Navigator& nav = rig.nav;
  const LocalTangentFrame& frame = rig.frame;
  constexpr Nanoseconds kMs = 1ms;
  rig.Drive(kT0, kT0 + 10s);
  ASSERT_TRUE(nav.aligned());
  EXPECT_FALSE(nav.ImuLost());
  // WHEN the IMU falls silent for 6 s while the fixes keep coming
  for (int k = 11; k <= 16; ++k) {
    rig.Fix(kT0 + k * 1000 * kMs);
    // THEN from the 4th fix after the last IMU sample (the one at 10 s counts) the solution is the
    // fix, flagged
    EXPECT_EQ(nav.ImuLost(), k >= 13) << "fix at " << k << " s";
  }
  const NavOutput lost = nav.Output();
  ASSERT_TRUE(lost.valid);
  EXPECT_EQ(lost.t, kT0 + 16'000 * kMs);
  EXPECT_TRUE(lost.status & kStatusImuLost);
  EXPECT_NEAR(frame.ToLocal(lost.position).x(), 16.0, 1e-6);
  EXPECT_EQ(nav.stats().imu_losses, 1u);
  EXPECT_TRUE(nav.stats().imu_lost);
  // WHEN the IMU comes back: the filter restarts at the next fix and tracks the vehicle again
  const std::uint64_t resets = nav.stats().gnss_resets;
  rig.Drive(kT0 + 16s, kT0 + 22s);
  EXPECT_FALSE(nav.ImuLost());
  EXPECT_EQ(nav.stats().gnss_resets, resets + 1);
  const NavOutput back = nav.Output();
  ASSERT_TRUE(back.valid);
  EXPECT_FALSE(back.status & kStatusImuLost);
  EXPECT_EQ(back.t, kT0 + 22'000 * kMs);
  EXPECT_LT((frame.ToLocal(back.position) - Eigen::Vector3d(22.0, 0, 0)).head<2>().norm(), 0.3);
}

// issue 15.12: an RMC with a speed and an empty course is a speed without a direction. The fix
// passes through with the speed reported and no velocity (not a velocity of 0 as if known).
TEST(NavigatorTest, GnssOnlyFixWithSpeedButNoCourseReportsTheSpeedAndNoVelocity) {
  NavigatorParams p;
  p.mode = NavMode::kGnssOnly;
  Navigator nav(p);
  GnssSample g;
  g.t = kT0;
  g.position = {51.925907, 4.5776455, 42.0};
  g.ground_speed_mps = 0.109;  // what ublox-lea-5h.log's receiver said, course field empty
  nav.Push(g);
  NavOutput o = nav.Output();
  ASSERT_TRUE(o.valid);
  EXPECT_FALSE(o.has_velocity);
  ASSERT_TRUE(o.ground_speed_mps.has_value());
  EXPECT_DOUBLE_EQ(*o.ground_speed_mps, 0.109);
  // the next fix has a course: the velocity is known again
  g.t += std::chrono::seconds(1);
  g.has_velocity = true;
  g.vel_enu_mps = {0.1, 0.2, 0.0};
  nav.Push(g);
  o = nav.Output();
  EXPECT_TRUE(o.has_velocity);
  EXPECT_NEAR(o.v_N_mps.y(), 0.2, 1e-12);
}

// issue 39: the tractor rig's RTK fixes at HDOP 2.19 and VDOP 6.31 (GSA). Scaled by the HDOP, the
// correlated height error was modelled at 0.015 × 2.19 = 3.3 cm where the receiver's was
// 0.015 × 6.31 / 1.6 = 5.9 cm, and the geoid separation's rounding (a height error common to every
// fix) was left out of the σ: mean vertical NEES 4.8 (tractor_autosteer_slcan) and 10.5
// (rtk_f9p_base_20km), 2.52 the bound. The height's correlated error now follows the VDOP, and the
// reported height σ holds the fixes' common error.
TEST(NavigatorTest, HeightErrorModelFollowsTheVdopAndTheReportedSigmaHoldsTheDatumRounding) {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.ekf.gnss_error_tau_s = 30.0;
  p.ekf.gnss_error_std_m = 0.008;
  p.ekf.gnss_error_vertical_std_m = 0.015;
  Navigator nav(p);
  const Lla origin{45.75, 126.63, 150.0};
  const LocalTangentFrame frame(origin);
  const double g0 = NormalGravity(origin.lat_deg, origin.height_m);
  const double datum_std_m = 0.1 / std::sqrt(12.0);
  constexpr Nanoseconds kMs = 1ms;
  // GIVEN a level vehicle driving east at 1 m/s, RTK fixed fixes at 10 Hz that report their DOPs
  for (GpsTime t = kT0 + 10 * kMs; t <= kT0 + 20'000 * kMs; t += 10 * kMs) {
    ImuSample s;
    s.t = t;
    s.dt_s = 0.01;
    s.delta_velocity_B_mps = Eigen::Vector3d(0, 0, g0 * 0.01);
    nav.Push(s);
    if ((t - kT0) % (100 * kMs) == 0ns) {
      GnssSample g;
      g.t = t;
      g.position =
          frame.ToLla(Eigen::Vector3d(static_cast<double>((t - kT0).count()) * 1e-9, 0, 0));
      g.pos_std_enu_m = Eigen::Vector3d(0.005, 0.005, 0.03);
      g.fix_quality = 4;
      g.hdop = 2.19;
      g.vdop = 6.31;
      g.height_datum_std_m = datum_std_m;
      g.has_velocity = true;
      g.vel_enu_mps = Eigen::Vector3d(1, 0, 0);
      g.vel_std_enu_mps = Eigen::Vector3d::Constant(0.05);
      nav.Push(g);
    }
    nav.Update();
  }
  ASSERT_TRUE(nav.aligned());
  // THEN the correlated height error's σ, even after 20 s of fixes (updates only shrink it), is
  // above the HDOP-scaled 3.3 cm and at most the VDOP-scaled 5.9 cm
  const EkfMatrix& P = nav.ekf().covariance();
  const double e_up_std_m = std::sqrt(P(ekf_index::kGnssError + 2, ekf_index::kGnssError + 2));
  EXPECT_GT(e_up_std_m, 0.015 * 2.19 * 1.2);
  EXPECT_LE(e_up_std_m, 0.015 * 6.31 / 1.6 + 1e-9);
  // AND the horizontal axes still follow the HDOP
  EXPECT_LE(std::sqrt(P(ekf_index::kGnssError, ekf_index::kGnssError)), 0.008 * 2.19 + 1e-9);
  // AND the reported height σ holds the geoid rounding beside the filter's own variance
  const NavOutput o = nav.Output();
  const double p_up_var = P(ekf_index::kPos + 2, ekf_index::kPos + 2);
  EXPECT_NEAR(o.pos_std_enu_m.z(), std::sqrt(p_up_var + datum_std_m * datum_std_m), 1e-12);
  EXPECT_NEAR(o.pos_std_enu_m.x(), std::sqrt(P(ekf_index::kPos, ekf_index::kPos)), 1e-12);
}

// The navigator's north error after 20 s of RTK fixed fixes on the truth and then 8 s of RTK float
// fixes 1 m north of it (a new float, its error persisting), each float fix as `float_fix` makes
// it.
double NorthErrorAfterAFloatOneMetreOff(
    const std::function<GnssSample(GpsTime, const Lla&)>& float_fix, bool float_from_receiver) {
  NavigatorParams p;
  p.ekf.gnss_float_error_from_receiver = float_from_receiver;
  p.mode = NavMode::kEkf;
  p.ekf.gnss_error_tau_s = 30.0;  // the tractor rig's navd tuning
  p.ekf.gnss_error_std_m = 0.008;
  p.ekf.gnss_float_error_tau_s = 5.0;
  p.ekf.gnss_float_error_std_m = 0.2;
  Navigator nav(p);
  const Lla origin{45.75, 126.63, 150.0};
  const LocalTangentFrame frame(origin);
  const double g0 = NormalGravity(origin.lat_deg, origin.height_m);
  constexpr Nanoseconds kMs = 1ms;
  const GpsTime t_float = kT0 + 20'000 * kMs;
  for (GpsTime t = kT0 + 10 * kMs; t <= kT0 + 28'000 * kMs; t += 10 * kMs) {
    ImuSample s;
    s.t = t;
    s.dt_s = 0.01;
    s.delta_velocity_B_mps = Eigen::Vector3d(0, 0, g0 * 0.01);
    nav.Push(s);
    if ((t - kT0) % (200 * kMs) == 0ns) {  // 5 Hz, driving east at 1 m/s
      const double e_m = static_cast<double>((t - kT0).count()) * 1e-9;
      GnssSample g;
      if (t < t_float) {
        g.t = t;
        g.position = frame.ToLla(Eigen::Vector3d(e_m, 0, 0));
        g.pos_std_enu_m = Eigen::Vector3d(0.01, 0.01, 0.02);
        g.fix_quality = 4;
        g.has_velocity = true;
        g.vel_enu_mps = Eigen::Vector3d(1, 0, 0);
        g.vel_std_enu_mps = Eigen::Vector3d::Constant(0.05);
      } else {
        g = float_fix(t, frame.ToLla(Eigen::Vector3d(e_m, 1.0, 0)));
      }
      nav.Push(g);
    }
    nav.Update();
  }
  EXPECT_TRUE(nav.aligned());
  return frame.ToLocal(nav.Output().position).y();
}

TEST(NavigatorTest, ANavPvtFloatFixWithHAccOneMetreIsWeightedByIt) {
  // GIVEN the float fixes as NAV-PVT gives them: carrSoln 1, hAcc 1 m, vAcc 2 m, sAcc 5 cm/s
  const auto pvt = [](GpsTime t, const Lla& at) {
    drivers::UbxMessage m;
    m.cls = 0x01, m.id = 0x07;
    m.flags = 0x01 | 0x02 | (1 << 6);
    m.gps_fix = 3;
    m.utc_valid = 0x07;
    const std::int64_t unix_s = UnixNsFromGpsTime(t, 18) / kNsPerSecond;
    const std::int64_t day_s = unix_s % 86400, days = unix_s / 86400;
    const std::chrono::year_month_day ymd{std::chrono::sys_days{std::chrono::days{days}}};
    m.year = static_cast<int>(ymd.year()), m.month = static_cast<int>(unsigned(ymd.month()));
    m.day = static_cast<int>(unsigned(ymd.day()));
    m.hour = static_cast<int>(day_s / 3600), m.minute = static_cast<int>(day_s / 60 % 60);
    m.second = static_cast<int>(day_s % 60);
    m.utc_nano_ns = static_cast<std::int32_t>(UnixNsFromGpsTime(t, 18) % kNsPerSecond);
    m.itow_ms = static_cast<std::uint32_t>(ToNs(t) / 1'000'000 % (kSecondsPerGpsWeek * 1000));
    m.lat_deg = at.lat_deg, m.lon_deg = at.lon_deg, m.height_m = at.height_m;
    m.h_msl_m = at.height_m;
    m.h_acc_m = 1.0, m.v_acc_m = 2.0;
    m.vel_e_mps = 1.0, m.s_acc_mps = 0.05;
    const auto g = drivers::NavPvtToGnssSample(m, 18, {});
    EXPECT_TRUE(g && g->t == t && g->fix_quality == 5);
    return g.value_or(GnssSample{});
  };
  // AND the same fixes as a GGA quality 5 gives them, with a configured float σ of 2 cm
  const auto gga = [&pvt](GpsTime t, const Lla& at) {
    GnssSample g = pvt(t, at);
    g.pos_std_enu_m = Eigen::Vector3d(0.02, 0.02, 0.04);
    g.receiver_h_std_m = 0;
    return g;
  };
  const double by_hacc_m = NorthErrorAfterAFloatOneMetreOff(pvt, false);
  const double by_hacc_model_m = NorthErrorAfterAFloatOneMetreOff(pvt, true);
  const double by_config_m = NorthErrorAfterAFloatOneMetreOff(gga, false);
  // THEN at the configured σ the float pulls the estimate by decimetres in 8 s (0.14 m measured;
  // the float error model, 0.2 m, absorbs the rest), weighted by its hAcc (white σ 1.06 m) by
  // half that (6.4 cm measured), and with the float error model sized by hAcc too (0.71 m,
  // gnss_float_error_from_receiver) by about a centimetre (1.1 cm measured)
  EXPECT_GT(by_config_m, 0.10);
  EXPECT_LT(by_hacc_m, 0.5 * by_config_m);
  EXPECT_LT(by_hacc_model_m, 0.03);
}

}  // namespace
}  // namespace hil::estimator

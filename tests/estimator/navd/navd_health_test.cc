// navd's fault detection (navd_health.h): MCU resets from a tick and sequence restart, IMU gaps,
// duplicated frames, GNSS gaps and outages, the J1939 IMU decoder's errors (CAN), and the health
// object appended to a JSON line.
#include "hil/estimator/navd/navd_health.h"

#include <string>

#include <gtest/gtest.h>

namespace hil::estimator {
namespace {

using drivers::McuFrame;

McuFrame Imu(std::uint16_t seq, std::uint32_t tick) {
  McuFrame f;
  f.type = McuFrame::Type::kImu;
  f.sequence = seq;
  f.tick = tick;
  return f;
}

GnssSample Fix(double t_s, int quality = 1) {
  GnssSample g;
  g.t = GpsTimeFromNs(static_cast<std::int64_t>(t_s * 1e9));
  g.fix_quality = quality;
  return g;
}

GpsTime Ns(double t_s) { return GpsTimeFromNs(static_cast<std::int64_t>(t_s * 1e9)); }

TEST(NavdHealthTest, DetectsAnMcuResetFromTheTickAndSequenceRestartingTogether) {
  NavdHealth h;
  std::uint16_t seq = 0;
  std::uint32_t tick = 10000;
  for (int k = 0; k < 500; ++k) h.OnMcuFrame(Imu(seq++, tick += 100000));
  EXPECT_EQ(h.counters().mcu_resets, 0u);
  EXPECT_EQ(h.counters().imu_gaps, 0u);
  // reset: silent, then boot STATUS with sequence 0 at tick ~0, then samples
  McuFrame status;
  status.type = McuFrame::Type::kStatus;
  status.sequence = 0;
  status.tick = 5;
  status.nominal_imu_period_ticks = 100000;
  h.OnMcuFrame(status);
  seq = 1;
  tick = 10000;
  for (int k = 0; k < 10; ++k) h.OnMcuFrame(Imu(seq++, tick += 100000));
  EXPECT_EQ(h.counters().mcu_resets, 1u);
  EXPECT_EQ(h.counters().imu_gaps, 0u) << "the restart is a reset, not a gap";
  const std::string f = h.Field(Ns(100));
  EXPECT_NE(f.find("\"mcu_reset\""), std::string::npos) << f;
  EXPECT_NE(f.find("\"mcu_resets\":1"), std::string::npos) << f;
  // a sequence wrap with the tick running on is no reset
  NavdHealth w;
  w.OnMcuFrame(Imu(65534, 300000000));
  w.OnMcuFrame(Imu(65535, 300100000));
  w.OnMcuFrame(Imu(0, 300200000));
  EXPECT_EQ(w.counters().mcu_resets, 0u);
}

TEST(NavdHealthTest, CountsImuGapsAndRepeatedFrames) {
  NavdHealth h;
  h.OnMcuFrame(Imu(1, 100000));
  h.OnMcuFrame(Imu(2, 200000));
  h.OnMcuFrame(Imu(2, 200000));  // duplicate
  h.OnMcuFrame(Imu(3, 300000));
  h.OnMcuFrame(Imu(8, 800000));  // 5 periods later
  EXPECT_EQ(h.counters().imu_repeated_frames, 1u);
  EXPECT_EQ(h.counters().imu_gaps, 1u);
}

TEST(NavdHealthTest, FlagsAGnssOutageAndCountsTheGapWhenFixesReturn) {
  NavdHealth h;
  for (int k = 0; k < 10; ++k) h.OnGnss(Fix(k));
  EXPECT_EQ(h.Field(Ns(9.5)).find("\"gnss_outage\""), std::string::npos);
  for (int k = 10; k < 20; ++k) h.OnGnss(Fix(k, 0));  // no fix for 10 s
  EXPECT_EQ(h.Field(Ns(12.4)).find("\"gnss_outage\""), std::string::npos)
      << "a fix may take 3.5 s to reach the filter";
  EXPECT_NE(h.Field(Ns(19.5)).find("\"gnss_outage\""), std::string::npos);
  EXPECT_TRUE(h.gnss_outage());
  h.OnGnss(Fix(20));
  h.OnGnss(Fix(20));  // the same epoch again
  const std::string f = h.Field(Ns(20.1));
  EXPECT_EQ(f.find("\"flags\":[\"gnss_outage\""), std::string::npos) << f;
  EXPECT_EQ(h.counters().gnss_outages, 1u);
  EXPECT_EQ(h.counters().gnss_no_fix_epochs, 10u);
  EXPECT_EQ(h.counters().gnss_gaps, 1u);
  EXPECT_EQ(h.counters().gnss_repeated_epochs, 1u);
}

TEST(NavdHealthTest, AppendsTheHealthObjectInsideTheJsonLine) {
  drivers::NmeaDecoderStats nmea;
  nmea.bad_checksum = 4;
  NavdHealth h({&nmea, nullptr, nullptr, nullptr, nullptr});
  std::string line = "{\"tov_utc_s\":1.0,\"status\":0}\n";
  h.AppendTo(line, Ns(1));
  EXPECT_EQ(line.rfind(
                "{\"tov_utc_s\":1.0,\"status\":0,\"health\":{\"flags\":[\"gnss_link_errors\"],", 0),
            0u)
      << line;
  EXPECT_NE(line.find("\"gnss_checksum_errors\":4"), std::string::npos);
  EXPECT_EQ(line.substr(line.size() - 3), "}}\n");
  // the link-error flag holds for 5 s after the last new error
  std::string later = "{}";
  h.AppendTo(later, Ns(7));
  EXPECT_EQ(later.find("gnss_link_errors"), std::string::npos) << later;
}

// A J1939 frame of the IMU (source 0xE2, priority 3) with 8 zero data bytes (valid values).
drivers::CanRxFrame J1939(std::uint32_t pgn, double rx_s) {
  drivers::CanRxFrame f;
  f.id = (3u << 26) | (pgn << 8) | 0xE2u;
  f.len = 8;
  f.rx_ns = static_cast<std::int64_t>(rx_s * 1e9);
  return f;
}

TEST(NavdHealthTest, ReportsTheJ1939DecodersUnpairedFramesAndRaisesTheImuLinkFlag) {
  drivers::J1939ImuDecoder can;
  NavdHealth h({nullptr, nullptr, nullptr, nullptr, nullptr, &can.stats()});
  // in order: ARI then ACCS of each sample, 10 ms apart
  for (int k = 0; k < 5; ++k) {
    can.Add(J1939(drivers::kPgnAri, 0.1 * k));
    can.Add(J1939(drivers::kPgnAccs, 0.1 * k + 0.0002));
  }
  std::string clean = h.Field(Ns(1));
  EXPECT_NE(clean.find("\"imu_can_unpaired\":0"), std::string::npos) << clean;
  EXPECT_EQ(clean.find("imu_link_errors"), std::string::npos) << clean;
  // one pair swapped on the bus (the harness's can_reorder): the ACCS comes without its ARI, and
  // the ARI that follows it is left without an ACCS when the next sample's ARI arrives
  can.Add(J1939(drivers::kPgnAccs, 0.5));
  can.Add(J1939(drivers::kPgnAri, 0.5002));
  can.Add(J1939(drivers::kPgnAri, 0.6));
  can.Add(J1939(drivers::kPgnAccs, 0.6002));
  EXPECT_EQ(can.stats().unpaired, 2u);
  const std::string f = h.Field(Ns(2));
  EXPECT_NE(f.find("\"imu_can_unpaired\":2"), std::string::npos) << f;
  EXPECT_NE(f.find("\"imu_link_errors\""), std::string::npos) << f;
  // a short frame and a receive time going back count too, and keep the flag up
  drivers::CanRxFrame short_frame = J1939(drivers::kPgnAri, 0.7);
  short_frame.len = 6;
  can.Add(short_frame);
  can.Add(J1939(drivers::kPgnSsi2, 0.55));  // received before the last frame
  const std::string g = h.Field(Ns(6.5));
  EXPECT_NE(g.find("\"imu_can_bad_length\":1"), std::string::npos) << g;
  EXPECT_NE(g.find("\"imu_can_out_of_order\":1"), std::string::npos) << g;
  EXPECT_NE(g.find("\"imu_link_errors\""), std::string::npos) << g;
  // and the flag falls 5 s after the last new error
  EXPECT_EQ(h.Field(Ns(12)).find("imu_link_errors"), std::string::npos);
}

TEST(NavdHealthTest, WithoutACanImuTheCanCountersAreZero) {
  NavdHealth h;
  const std::string f = h.Field(Ns(1));
  EXPECT_NE(f.find("\"imu_can_unpaired\":0,\"imu_can_bad_length\":0,\"imu_can_out_of_order\":0}"),
            std::string::npos)
      << f;
}

TEST(NavdHealthTest, FlagsTheImuLostWhileTheNavigatorSaysSo) {
  NavigatorStats nav;
  NavdHealth h(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  EXPECT_EQ(h.Field(Ns(1)).find("imu_lost"), std::string::npos);
  nav.imu_lost = true;
  nav.imu_losses = 1;
  const std::string lost = h.Field(Ns(2));
  EXPECT_NE(lost.find("\"flags\":[\"imu_lost\"]"), std::string::npos) << lost;
  EXPECT_NE(lost.find("\"imu_losses\":1"), std::string::npos) << lost;
  nav.imu_lost = false;
  const std::string back = h.Field(Ns(3));
  EXPECT_EQ(back.find("\"imu_lost\""), std::string::npos) << back;
  EXPECT_NE(back.find("\"imu_losses\":1"), std::string::npos) << back;
}

// issue 39: each aid source's innovation window against its χ² band, and the adaptation's state
TEST(NavdHealthTest, ReportsEachAidSourcesInnovationWindowAndTheAdaptation) {
  NavigatorStats nav;
  nav.aid[kAidGnssPosition].accepted = 40;
  nav.aid[kAidGnssPosition].rejected = 2;
  nav.aid[kAidGnssPosition].window_nis_per_dof = 1.5;
  nav.aid[kAidGnssPosition].window_count = 20;
  nav.aid[kAidGnssPosition].band_low = 0.675;
  nav.aid[kAidGnssPosition].band_high = 1.39;
  nav.process_noise_scale = 4;
  nav.fadings = 3;
  nav.stationary = true;
  NavdHealth h(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string f = h.Field(Ns(1));
  EXPECT_NE(f.find("\"aid\":{\"gnss_pos\":{\"accepted\":40,\"rejected\":2,\"last_nis\":0,"
                   "\"window_nis_per_dof\":1.5,\"window_count\":20,\"band\":[0.675,1.39],"),
            std::string::npos)
      << f;
  for (const char* key : {"\"gnss_vel\":{", "\"nhc\":{", "\"zupt\":{", "\"zaru\":{",
                          "\"process_noise_scale\":4,", "\"fadings\":3,", "\"stationary\":true}"})
    EXPECT_NE(f.find(key), std::string::npos) << key << " in " << f;
  // the keys that were there before stay
  EXPECT_NE(f.find("\"imu_can_out_of_order\":0,"), std::string::npos) << f;
}

// issue 41: an IMU found far outside its noise model is said in the health output (and only then)
TEST(NavdHealthTest, ReportsTheAccelerometerNoiseScaleOnceRaised) {
  NavigatorStats nav;
  NavdHealth quiet(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  EXPECT_EQ(quiet.Field(Ns(1)).find("accel_noise"), std::string::npos);
  nav.accel_noise_scale = 250;
  nav.accel_noise_raises = 3;
  NavdHealth h(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string f = h.Field(Ns(1));
  EXPECT_NE(f.find("\"accel_noise_scale\":250,\"accel_noise_raises\":3"), std::string::npos) << f;
}

// issue 39: the x and y gyros' scale factors, while estimated, are in the health line (ppm)
TEST(NavdHealthTest, ReportsTheXAndYGyroScalesWhileEstimated) {
  NavigatorStats nav;
  NavdHealth quiet(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  EXPECT_EQ(quiet.Field(Ns(1)).find("gyro_scale_xy"), std::string::npos);
  nav.gyro_scale_xy_estimated = true;
  nav.gyro_scale_xy = {0.0123, -0.004};
  nav.gyro_scale_xy_std = {0.002, 0.0031};
  NavdHealth h(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string f = h.Field(Ns(1));
  EXPECT_NE(f.find("\"gyro_scale_xy_ppm\":{\"x\":12300,\"y\":-4000,\"x_std\":2000,"
                   "\"y_std\":3100}"),
            std::string::npos)
      << f;
}

// issues 41/39: an IMU found unusable (ImuUsabilityCheck) is a flag while it lasts, and the test's
// statistic is reported once it has fired (the line stays short before)
TEST(NavdHealthTest, ReportsAnUnusableImuAndItsTestStatistic) {
  NavigatorStats nav;
  nav.imu_consistency_tests = 12;
  nav.imu_consistency_stat = 3.5;
  NavdHealth quiet(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string before = quiet.Field(Ns(1));
  EXPECT_EQ(before.find("imu_unusable"), std::string::npos) << before;
  EXPECT_EQ(before.find("imu_consistency"), std::string::npos) << before;
  nav.imu_unusable = true;
  nav.imu_consistency_stat = 180.25;
  nav.imu_consistency_threshold = 37.51;
  nav.imu_unusable_periods = 1;
  NavdHealth h(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string f = h.Field(Ns(1));
  EXPECT_NE(f.find("\"flags\":[\"imu_unusable\"]"), std::string::npos) << f;
  EXPECT_NE(f.find("\"imu_consistency\":{\"unusable\":true,\"stat\":180.2,\"threshold\":37.51,"
                   "\"tests\":12,\"unusable_periods\":1}"),
            std::string::npos)
      << f;
  // back to the INS: the flag goes, the figures stay
  nav.imu_unusable = false;
  NavdHealth back(HealthSources{nullptr, nullptr, nullptr, nullptr, &nav});
  const std::string g = back.Field(Ns(1));
  EXPECT_EQ(g.find("\"flags\":[\"imu_unusable\"]"), std::string::npos) << g;
  EXPECT_NE(g.find("\"imu_consistency\":{\"unusable\":false,"), std::string::npos) << g;
}

}  // namespace
}  // namespace hil::estimator

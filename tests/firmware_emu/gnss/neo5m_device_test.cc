#include "hil/firmware_emu/gnss/neo5m_device.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss {
namespace {

TruthSample Truth(Time t, double lat = 35.4796096, double lon = 50.5979765, double v_east = 0.0) {
  TruthSample s;
  s.t = t;
  s.lat_deg = lat;
  s.lon_deg = lon;
  s.height_m = 1312.0;
  s.v_NB_N_mps = Eigen::Vector3d(v_east, 0, 0);
  return s;
}

struct Harness {
  explicit Harness(Neo5mConfig cfg, std::uint64_t seed = 3) : dev(cfg, seed) {}
  /// Runs epochs up to `t_end_s` and returns what came out.
  std::vector<SerialMessage> RunUntil(double t_end_s, double lat = 35.4796096,
                                      double lon = 50.5979765) {
    std::vector<SerialMessage> got;
    while (dev.next_event_time() <= TimeFromSeconds(t_end_s)) {
      DeviceOutput out;
      dev.OnEvent(Truth(dev.next_event_time(), lat, lon), out);
      got.insert(got.end(), out.serial.begin(), out.serial.end());
      fixes.push_back(dev.last_fix());
    }
    return got;
  }
  std::vector<SerialMessage> Host(const std::string& bytes) {
    DeviceOutput out;
    dev.OnHostBytes(0, dev.next_event_time() - std::chrono::milliseconds(500), bytes, out);
    return out.serial;
  }
  double FirstFix_s() const {
    for (const auto& f : fixes) {
      if (f.valid()) return ToSeconds(f.t_validity);
    }
    return -1;
  }
  Neo5mDevice dev;
  std::vector<GnssFix> fixes;
};

Neo5mConfig Config(StartKind start = StartKind::kHot) {
  Neo5mConfig c;
  c.start_utc = ParseIsoUtc("2013-06-10T08:00:00Z");
  c.start = start;
  return c;
}

std::vector<std::string> Names(const std::vector<SerialMessage>& m) {
  std::vector<std::string> n;
  for (const auto& x : m) n.push_back(x.name);
  return n;
}

TEST(Neo5mDeviceTest, DefaultStreamIsBannerThenNmeaInReceiverOrder) {
  Harness h(Config());
  const auto first = h.RunUntil(0.0);
  std::vector<std::string> n = Names(first);
  ASSERT_GE(n.size(), 13u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(n[static_cast<std::size_t>(i)], "NMEA-TXT");
  EXPECT_EQ(first[0].bytes, "$GPTXT,01,01,02,u-blox ag - www.u-blox.com*50\r\n");
  EXPECT_EQ(first[1].bytes,
            "$GPTXT,01,01,02,HW  UBX-G50xx  00040005 *53\r\n");  // verbatim u-blox 5 line
  EXPECT_EQ(first[0].t_ready, TimeFromSeconds(0.1));
  const auto second = h.RunUntil(1.0);
  n = Names(second);
  ASSERT_GE(n.size(), 6u);
  EXPECT_EQ(n[0], "NMEA-RMC");
  EXPECT_EQ(n[1], "NMEA-VTG");
  EXPECT_EQ(n[2], "NMEA-GGA");
  EXPECT_EQ(n[3], "NMEA-GSA");
  EXPECT_EQ(n[4], "NMEA-GSV");
  EXPECT_EQ(n.back(), "NMEA-GLL");
  for (const auto& m : second) {
    EXPECT_EQ(m.bytes.rfind("$GP", 0), 0u) << m.bytes;  // no banner again, no UBX by default
    EXPECT_NE(m.bytes.find("*"), std::string::npos);
  }
}

TEST(Neo5mDeviceTest, TimeToFirstFixDependsOnTheStart) {
  Harness hot(Config(StartKind::kHot)), warm(Config(StartKind::kWarm)),
      cold(Config(StartKind::kCold));
  hot.RunUntil(40);
  warm.RunUntil(40);
  cold.RunUntil(40);
  EXPECT_DOUBLE_EQ(hot.FirstFix_s(), 1.0);
  EXPECT_DOUBLE_EQ(warm.FirstFix_s(), 28.0);
  EXPECT_DOUBLE_EQ(cold.FirstFix_s(), 29.0);
  EXPECT_EQ(cold.dev.last_epoch().status.ttff_ms, 29000u);
}

TEST(Neo5mDeviceTest, ColdStartHidesTimeAndOrbitsUntilKnown) {
  Harness h(Config(StartKind::kCold));
  auto out = h.RunUntil(0);
  std::string rmc, gsv;
  for (const auto& m : out) {
    if (m.name == "NMEA-RMC") rmc = m.bytes;
    if (m.name == "NMEA-GSV" && gsv.empty()) gsv = m.bytes;
  }
  EXPECT_EQ(rmc.rfind("$GPRMC,,V,,,,,,,,,,N*", 0), 0u) << rmc;
  // tracked satellites with C/N0 but no elevation/azimuth, as in the nl551e cold-start capture
  EXPECT_NE(gsv.find(",,,"), std::string::npos) << gsv;
}

TEST(Neo5mDeviceTest, CfgRstColdRestartsAcquisitionAndRepeatsTheBanner) {
  Harness h(Config());
  h.RunUntil(5);
  ASSERT_TRUE(h.dev.last_fix().valid());
  const auto replies =
      h.Host(ubx::Frame(0x06, 0x04, std::vector<std::uint8_t>{0xFF, 0xFF, 0x01, 0x00}));
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].name, "UBX-ACK-ACK");
  const auto out = h.RunUntil(40);
  EXPECT_EQ(out[0].name, "NMEA-TXT");
  int first_valid = -1;
  for (const auto& f : h.fixes) {
    if (ToSeconds(f.t_validity) > 5.5 && f.valid()) {
      first_valid = static_cast<int>(ToSeconds(f.t_validity));
      break;
    }
  }
  EXPECT_EQ(first_valid,
            6 + 29 - 1 + 1);  // reset at 5.5 s, first epoch 6 s; TTFF 29 s from the reset
}

TEST(Neo5mDeviceTest, OutageDropsTheFixAndReacquires) {
  Neo5mConfig c = Config();
  c.faults.push_back({GnssFault::Kind::kOutage, TimeFromSeconds(10), TimeFromSeconds(20)});
  Harness h(c);
  h.RunUntil(30);
  for (const auto& f : h.fixes) {
    const double t = ToSeconds(f.t_validity);
    if (t >= 10 && t < 20) {
      EXPECT_FALSE(f.valid()) << t;
    }
    if (t >= 2 && t < 10) {
      EXPECT_TRUE(f.valid()) << t;
    }
    if (t >= 21) {
      EXPECT_TRUE(f.valid()) << t;  // re-acquisition 1 s
    }
  }
  EXPECT_FALSE(h.fixes[20].valid());
}

TEST(Neo5mDeviceTest, ObstructionLeavesFewerSatellitesAndWorseDop) {
  Neo5mConfig c = Config();
  c.faults.push_back(
      {GnssFault::Kind::kObstruction, TimeFromSeconds(10), TimeFromSeconds(20), 40.0});
  Harness h(c);
  h.RunUntil(15);
  const GnssFix& open = h.fixes[5];
  const GnssFix& blocked = h.fixes[15];
  EXPECT_LT(blocked.num_sv, open.num_sv);
  if (blocked.valid()) {
    EXPECT_GT(blocked.hdop, open.hdop);
  }
}

TEST(Neo5mDeviceTest, StepGlitchMovesThePosition) {
  Neo5mConfig c = Config();
  c.faults.push_back({GnssFault::Kind::kStep, TimeFromSeconds(10), TimeFromSeconds(20), 0,
                      Eigen::Vector3d(0, 50, 0)});
  Harness h(c);
  h.RunUntil(12);
  const double dlat_m = (h.fixes[11].lat_deg - h.fixes[9].lat_deg) * 111000.0;
  EXPECT_NEAR(dlat_m, 50.0, 3.0);
}

TEST(Neo5mDeviceTest, OverloadOutputsMoreThanTheBaudCarriesAndOnlyWhileActive) {
  Neo5mConfig c = Config();
  c.faults.push_back({GnssFault::Kind::kOverload, TimeFromSeconds(10), TimeFromSeconds(20)});
  Harness h(c);
  const auto per_epoch = [&](double from_s, double to_s) {
    std::size_t bytes = 0, epochs = 0;
    std::set<std::string> names;
    for (const auto& m : h.RunUntil(to_s)) {
      const double t = ToSeconds(m.t_ready);
      if (t < from_s) continue;
      bytes += m.bytes.size();
      names.insert(m.name);
    }
    epochs = static_cast<std::size_t>(to_s - from_s);
    return std::make_pair(bytes / epochs, names);
  };
  auto [normal, normal_names] = per_epoch(0, 9);
  normal_names.erase("NMEA-TXT");  // the power-up banner
  const auto [overload, overload_names] = per_epoch(10, 19);
  const auto [after, after_names] = per_epoch(21, 29);
  // 9600 baud 8N1 carries 960 bytes per second
  EXPECT_LT(normal, 960u);
  EXPECT_GT(overload, 960u) << "the overloaded output exceeds the line";
  EXPECT_EQ(overload_names.count("UBX-NAV-SOL"), 1u);
  EXPECT_EQ(overload_names.count("NMEA-ZDA"), 1u);
  EXPECT_NEAR(static_cast<double>(after), static_cast<double>(normal),
              0.1 * static_cast<double>(normal))
      << "back to the configured output after the fault";
  EXPECT_EQ(after_names, normal_names);
  EXPECT_EQ(h.dev.overloaded_epochs(), 10u);
}

TEST(Neo5mDeviceTest, CfgMsgEnablesUbxNavMessagesAfterTheAck) {
  Harness h(Config());
  h.RunUntil(2);
  auto r = h.Host(ubx::Frame(0x06, 0x01, std::vector<std::uint8_t>{0x01, 0x06, 0x01}) +
                  ubx::Frame(0x06, 0x01, std::vector<std::uint8_t>{0x01, 0x30, 0x01}) +
                  ubx::Frame(0x06, 0x01, std::vector<std::uint8_t>{0xF0, 0x03, 0x00}));
  ASSERT_EQ(Names(r), (std::vector<std::string>{"UBX-ACK-ACK", "UBX-ACK-ACK", "UBX-ACK-ACK"}));
  const auto out = h.RunUntil(3);
  const auto n = Names(out);
  EXPECT_EQ(n[0], "UBX-NAV-SOL");
  EXPECT_EQ(n[1], "UBX-NAV-SVINFO");
  for (const auto& x : n) EXPECT_NE(x, "NMEA-GSV");
  // SVINFO: chip generation of a u-blox 5
  const std::string& sv = out[1].bytes;
  EXPECT_EQ(static_cast<std::uint8_t>(sv[6 + 5]) & 0x07, 1);
  // SOL: fix 3D, gpsFixOk, week and TOW set; the iTOW is the epoch's GPS time of week
  const std::string& sol = out[0].bytes;
  const std::vector<std::uint8_t> p(sol.begin() + 6, sol.end() - 2);
  ASSERT_EQ(p.size(), 52u);
  ubx::Reader rd(p);
  const GpsWeekTime g = GpsFrom(ParseIsoUtc("2013-06-10T08:00:03Z"));
  EXPECT_EQ(rd.U4(0), g.itow_ms());
  EXPECT_EQ(rd.I2(8), g.week);
  EXPECT_EQ(rd.U1(10), 3);
  EXPECT_EQ(rd.U1(11), 0x0D);
}

TEST(Neo5mDeviceTest, CfgPrtChangesTheBaudBeforeTheAck) {
  Harness h(Config());
  h.RunUntil(1);
  ubx::Writer w;
  w.U1(1).U1(0).U2(0).U4(0x8D0).U4(38400).U2(0x07).U2(0x03).U2(0).U2(0);
  EXPECT_EQ(h.dev.baud(0), 9600);
  const auto r = h.Host(ubx::Frame(0x06, 0x00, w));
  EXPECT_EQ(h.dev.baud(0), 38400);  // the scheduler reads this before queueing the ACK
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].name, "UBX-ACK-ACK");
}

// Issue 40 (minor): host bytes reach the receiver at its baud. Two commands in one write are
// whole after their own bytes and those before them have arrived (10 bit times a byte at 9600
// Bd); a write while the line still carries the last one queues behind it. Each answer is ready
// `response_delay` after its command is whole (before: 10 ms after the write, whatever its length).
TEST(Neo5mDeviceTest, HostBytesArriveAtTheBaud) {
  Harness h(Config());
  h.RunUntil(1);
  const std::string msg = ubx::Frame(0x06, 0x01, std::vector<std::uint8_t>{0x01, 0x06, 0x01});
  const std::string rate =
      ubx::Frame(0x06, 0x08, std::vector<std::uint8_t>{0xE8, 0x03, 0x01, 0x00, 0x01, 0x00});
  ASSERT_EQ(msg.size() + rate.size(), 25u);
  const Time t0 = TimeFromSeconds(1.5);
  const Duration byte{1041667};  // 10 / 9600 s
  const Duration delay = Neo5mConfig{}.response_delay;
  DeviceOutput out;
  h.dev.OnHostBytes(0, t0, msg + rate, out);
  ASSERT_EQ(out.serial.size(), 2u);
  EXPECT_EQ(out.serial[0].name, "UBX-ACK-ACK");
  EXPECT_EQ(out.serial[0].t_ready, t0 + byte * 11 + delay);
  EXPECT_EQ(out.serial[1].t_ready, t0 + byte * 25 + delay);
  EXPECT_TRUE(out.serial[0].reply);
  DeviceOutput poll;
  h.dev.OnHostBytes(0, t0 + std::chrono::milliseconds(5),
                    ubx::Frame(0x0A, 0x04, std::vector<std::uint8_t>{}), poll);
  ASSERT_EQ(poll.serial.size(), 1u);
  EXPECT_EQ(poll.serial[0].t_ready, t0 + byte * 33 + delay) << "behind the 25 bytes on the line";
  // a write on an idle line: its own length only
  DeviceOutput later;
  const Time t1 = TimeFromSeconds(1.7);
  h.dev.OnHostBytes(0, t1, msg, later);
  ASSERT_EQ(later.serial.size(), 1u);
  EXPECT_EQ(later.serial[0].t_ready, t1 + byte * 11 + delay);
}

TEST(Neo5mDeviceTest, CfgRateRaisesTheEpochRate) {
  Harness h(Config());
  h.RunUntil(2);
  h.Host(ubx::Frame(0x06, 0x08, std::vector<std::uint8_t>{0xFA, 0x00, 0x01, 0x00, 0x01, 0x00}));
  const std::size_t before = h.fixes.size();
  h.RunUntil(4);
  EXPECT_EQ(h.fixes.size() - before, 8u);  // 2.25, 2.5, … 4.0
  EXPECT_EQ(ToNs(h.fixes[before + 1].t_validity) - ToNs(h.fixes[before].t_validity), 250000000);
}

TEST(Neo5mDeviceTest, PollsMonVerAndPubx) {
  Harness h(Config());
  h.RunUntil(3);
  auto r = h.Host(ubx::Frame(0x0A, 0x04, std::vector<std::uint8_t>{}));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].name, "UBX-MON-VER");
  EXPECT_EQ(r[0].bytes.size(), 6u + 40u + 30u + 2u);
  EXPECT_EQ(r[0].bytes.substr(6, 12), "6.02 (36023)");
  EXPECT_EQ(r[0].bytes.substr(36, 8), "00040005");
  r = h.Host("$PUBX,00*33\r\n$PUBX,04*37\r\n");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].bytes.rfind("$PUBX,00,080003.00,3528.", 0), 0u) << r[0].bytes;
  EXPECT_NE(r[0].bytes.find(",G3,"), std::string::npos) << r[0].bytes;
  EXPECT_EQ(r[1].bytes.rfind("$PUBX,04,080003.00,100613,", 0), 0u) << r[1].bytes;
}

TEST(Neo5mDeviceTest, SouthWestHemispheresAndMidnightRollover) {
  Neo5mConfig c = Config();
  c.start_utc = ParseIsoUtc("2016-12-31T23:59:58Z");  // the 2016 leap second follows
  Harness h(c);
  const auto out = h.RunUntil(3, -33.8688, -70.6693);
  std::vector<std::string> rmc;
  for (const auto& m : out) {
    if (m.name == "NMEA-RMC") rmc.push_back(m.bytes);
  }
  ASSERT_EQ(rmc.size(), 4u);
  EXPECT_NE(rmc[1].find(",235959.00,A,3352."), std::string::npos) << rmc[1];
  EXPECT_NE(rmc[1].find(",S,07040."), std::string::npos) << rmc[1];
  EXPECT_NE(rmc[1].find(",W,"), std::string::npos) << rmc[1];
  EXPECT_NE(rmc[1].find(",311216,"), std::string::npos) << rmc[1];
  EXPECT_NE(rmc[2].find(",000000.00,A,"), std::string::npos) << rmc[2];
  EXPECT_NE(rmc[2].find(",010117,"), std::string::npos) << rmc[2];
  EXPECT_EQ(h.dev.last_epoch().leap_s, 18);
}

TEST(Neo5mDeviceTest, ReportedAccuracyMatchesTheActualError) {
  Neo5mConfig c = Config();
  Harness h(c, 11);
  double sum_e2 = 0, sum_hacc2 = 0;
  int n = 0;
  while (h.dev.next_event_time() <= TimeFromSeconds(3000)) {
    DeviceOutput out;
    const TruthSample t = Truth(h.dev.next_event_time());
    h.dev.OnEvent(t, out);
    const GnssFix& f = h.dev.last_fix();
    if (!f.valid()) continue;
    const double de =
        (f.lon_deg - t.lon_deg) * 111320.0 * std::cos(t.lat_deg * std::numbers::pi / 180);
    const double dn = (f.lat_deg - t.lat_deg) * 110950.0;
    sum_e2 += de * de + dn * dn;
    sum_hacc2 += f.h_acc_m * f.h_acc_m;
    ++n;
  }
  const double rms = std::sqrt(sum_e2 / n), hacc = std::sqrt(sum_hacc2 / n);
  std::printf("horizontal error RMS %.3f m, reported hAcc RMS %.3f m over %d fixes\n", rms, hacc,
              n);
  EXPECT_NEAR(rms / hacc, 1.0, 0.2) << "rms " << rms << " hAcc " << hacc;
}

TEST(Neo5mDeviceTest, ThreeReceiversShareTheCommonError) {
  // averaging three receivers helps only partly: RMS ratio √(c + (1−c)/3) ≈ 0.80 for c = 0.46
  std::vector<std::unique_ptr<Neo5mDevice>> rx;
  for (std::uint64_t i = 0; i < 3; ++i) {
    Neo5mConfig c = Config();
    c.common_seed = 999;
    rx.push_back(std::make_unique<Neo5mDevice>(c, 100 + 7 * i));
  }
  double single2 = 0, avg2 = 0;
  int n = 0;
  for (int k = 0; k < 20000; ++k) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (auto& d : rx) {
      DeviceOutput out;
      d->OnEvent(Truth(TimeFromSeconds(k)), out);
    }
    if (!rx[0]->last_fix().valid()) continue;
    // position errors relative to the truth: use the error model's state via the fix
    for (auto& d : rx) {
      const GnssFix& f = d->last_fix();
      sum += Eigen::Vector3d((f.lon_deg - 50.5979765) * 90000.0,
                             (f.lat_deg - 35.4796096) * 110950.0, 0);
    }
    const GnssFix& f0 = rx[0]->last_fix();
    single2 += std::pow((f0.lon_deg - 50.5979765) * 90000.0, 2) +
               std::pow((f0.lat_deg - 35.4796096) * 110950.0, 2);
    avg2 += (sum / 3.0).squaredNorm();
    ++n;
  }
  const double ratio = std::sqrt(avg2 / single2);
  std::printf("single receiver horizontal RMS %.3f m, mean of three %.3f m (ratio %.3f)\n",
              std::sqrt(single2 / n), std::sqrt(avg2 / n), ratio);
  EXPECT_NEAR(ratio, std::sqrt(0.46 + 0.54 / 3.0), 0.05);
}

TEST(Neo5mDeviceTest, RtkProfileIsTenHertzFloatThenFixed) {
  Neo5mConfig c = Config();
  c.profile = "rtk";
  Harness h(c);
  EXPECT_EQ(h.dev.baud(0), 115200);
  const auto out = h.RunUntil(40);
  std::vector<std::string> gga;
  for (const auto& m : out) {
    if (m.name == "NMEA-GGA") gga.push_back(m.bytes);
  }
  EXPECT_EQ(gga.size(), 401u);
  EXPECT_NE(gga[100].find(",5,"), std::string::npos) << gga[100];  // 10 s: float
  EXPECT_NE(gga[399].find(",4,"), std::string::npos) << gga[399];  // 39.9 s: fixed
  EXPECT_NE(gga[399].find("3528.77"), std::string::npos);
  const GnssFix& f = h.fixes.back();
  EXPECT_LT(std::abs(f.lat_deg - 35.4796096) * 110950.0, 0.05);
}

TEST(Neo5mDeviceTest, DataGapSilencesTheOutputButKeepsTheRtkFix) {
  Neo5mConfig c = Config();
  c.profile = "rtk";
  c.faults.push_back({GnssFault::Kind::kDataGap, TimeFromSeconds(40), TimeFromSeconds(50)});
  Harness h(c);
  const auto out = h.RunUntil(60);
  std::vector<std::string> gga;
  for (const auto& m : out) {
    const double t = ToSeconds(m.t_ready);
    EXPECT_FALSE(t > 40.2 && t < 50.0) << m.name << " sent at " << t << " s inside the data gap";
    if (m.name == "NMEA-GGA" && t > 50.0 && t < 50.2) gga.push_back(m.bytes);
  }
  ASSERT_EQ(gga.size(), 1u) << "the first epoch after the gap is sent";
  EXPECT_NE(gga[0].find(",4,"), std::string::npos)
      << "still RTK fixed, no re-acquisition: " << gga[0];
  for (const auto& f : h.fixes)
    EXPECT_TRUE(ToSeconds(f.t_validity) < 6 || f.valid()) << "the receiver keeps its fix";
}

}  // namespace
}  // namespace hil::gnss

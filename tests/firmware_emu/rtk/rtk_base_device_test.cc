// The emulated RTK base: the station message at start and every 10 s, an MSM every epoch with the
// station's id and the epoch's GPS time of week, the radio's byte rate, latency, seeded losses and
// outages, and the same bytes for the same seed.
#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_msm.h"
#include "hil/firmware_emu/rtk/rtcm3_station.h"

#include "rtk_base_fixture.h"

namespace hil::rtk {
namespace {

using test::KarajBase;

TruthSample At(double s) {
  TruthSample t;
  t.t = TimeFromSeconds(s);
  return t;
}

TEST(RtkBaseDevice, StationMessageEveryTenSecondsAndAnMsmEachEpoch) {
  RtkBaseDevice base(KarajBase(rtcm3::MsmKind::kMsm7), 1);
  EXPECT_EQ(base.next_event_time(), TimeFromNs(0));  // 08:00:00 UTC is on the grid
  const gnss::GpsWeekTime g0 = gnss::GpsFrom(gnss::ParseIsoUtc("2026-06-10T08:00:00Z"));
  for (int k = 0; k < 21; ++k) {
    const auto msgs = base.EncodeEpoch(TimeFromNs(k * 1000000000LL));
    ASSERT_EQ(msgs.size(), k % 10 == 0 ? 2U : 1U) << k;
    if (k % 10 == 0) {
      EXPECT_EQ(msgs[0].name, "RTCM3-1006");
      const auto st = rtcm3::DecodeStation(rtcm3::Split(msgs[0].bytes).bodies.at(0));
      EXPECT_EQ(st.station_id, 1234);
      EXPECT_NEAR(st.antenna_height_m, 1.5, 1e-9);
      EXPECT_LT((st.arp_E_m - base.station().arp_E_m).norm(), 1e-4);
    }
    const auto split = rtcm3::Split(msgs.back().bytes);
    ASSERT_EQ(split.bodies.size(), 1U);
    EXPECT_EQ(msgs.back().name, "RTCM3-1077");
    rtcm3::MsmKind kind{};
    const rtcm3::MsmEpoch e = rtcm3::DecodeGpsMsm(split.bodies[0], kind);
    EXPECT_EQ(e.station_id, 1234);
    EXPECT_EQ(e.epoch_time_ms, g0.itow_ms() + 1000U * static_cast<unsigned>(k));
    EXPECT_EQ(e.satellites.size(), base.last_msm().satellites.size());
  }
}

TEST(RtkBaseDevice, RadioTimesPacketsByByteRateAndLatency) {
  RtkBaseConfig c = KarajBase(rtcm3::MsmKind::kMsm4);
  c.radio.bytes_per_s = 1000.0;
  c.radio.latency = std::chrono::milliseconds(80);
  RtkBaseDevice base(c, 1);
  DeviceOutput out;
  base.OnEvent(At(0), out);
  ASSERT_EQ(out.serial.size(), 2U);
  const std::size_t bytes = out.serial[0].bytes.size() + out.serial[1].bytes.size();
  // handed over 30 ms after the epoch, on air bytes/1000 s, then 80 ms
  const Time expected =
      TimeFromNs(30000000LL + static_cast<std::int64_t>(bytes) * 1000000LL + 80000000LL);
  EXPECT_EQ(out.serial[0].t_ready, expected);
  EXPECT_EQ(out.serial[1].t_ready, expected);
  EXPECT_EQ(base.next_event_time(), TimeFromNs(1000000000LL));
}

std::vector<bool> Losses(std::uint64_t seed, double p, std::vector<RadioOutage> outages = {}) {
  RtkBaseConfig c = KarajBase(rtcm3::MsmKind::kMsm4);
  c.radio.loss_probability = p;
  c.radio.outages = std::move(outages);
  RtkBaseDevice base(c, seed);
  std::vector<bool> lost;
  for (int k = 0; k < 300; ++k) {
    DeviceOutput out;
    base.OnEvent(At(k), out);
    lost.push_back(out.serial.empty());
  }
  EXPECT_EQ(base.rtk_statistics().epochs, 300U);
  return lost;
}

TEST(RtkBaseDevice, SeededLossesAreDeterministic) {
  const auto a = Losses(5, 0.1), b = Losses(5, 0.1), c = Losses(6, 0.1);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  const auto n = std::count(a.begin(), a.end(), true);
  EXPECT_GE(n, 15);  // 30 expected; binomial(300, 0.1) lies in [15, 45] with p > 0.99
  EXPECT_LE(n, 45);
  const auto none = Losses(5, 0.0);
  EXPECT_EQ(std::count(none.begin(), none.end(), true), 0);
}

TEST(RtkBaseDevice, OutageCutsEveryPacketInItsWindow) {
  const auto lost = Losses(5, 0.0, {{TimeFromSeconds(100), TimeFromSeconds(130)}});
  for (int k = 0; k < 300; ++k)
    EXPECT_EQ(lost[static_cast<std::size_t>(k)], k >= 100 && k < 130) << k;
}

TEST(RtkBaseDevice, SameSeedSameBytes) {
  const std::string a = test::BaseStream(KarajBase(rtcm3::MsmKind::kMsm7), 30, 9);
  EXPECT_EQ(a, test::BaseStream(KarajBase(rtcm3::MsmKind::kMsm7), 30, 9));
  EXPECT_NE(a, test::BaseStream(KarajBase(rtcm3::MsmKind::kMsm7), 30, 10));
  const rtcm3::SplitResult r = rtcm3::Split(a);
  EXPECT_EQ(r.bodies.size(), 33U);  // 30 MSMs and 3 station messages
  EXPECT_EQ(r.crc_errors, 0U);
  EXPECT_EQ(r.skipped_bytes, 0U);
}

TEST(RtkBaseDevice, RejectsBadConfiguration) {
  RtkBaseConfig c = KarajBase(rtcm3::MsmKind::kMsm7);
  c.station_message = 1007;
  EXPECT_THROW(RtkBaseDevice(c, 1), std::invalid_argument);
  c.station_message = 1005;
  c.obs_rate_hz = 0;
  EXPECT_THROW(RtkBaseDevice(c, 1), std::invalid_argument);
}

}  // namespace
}  // namespace hil::rtk

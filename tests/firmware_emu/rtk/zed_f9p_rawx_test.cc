// The ZED-F9P's RXM-RAWX: its framing byte by byte (a golden of a hand-set epoch, and each field
// read back by its offset in the interface description's layout), the message enabled only by
// CFG-MSGOUT-UBX_RXM_RAWX_UART1 (a VALSET from the host), and its observations from the base's
// observation model: at the base's own antenna the double differences of the two receivers'
// phases are whole cycles (the geometry, the atmosphere and both clocks cancel) up to the noise
// and multipath, and those of the codes are metres at most.
#include <bit>
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_f9_rawx.h"
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

double R8(std::string_view p, std::size_t off) {
  return std::bit_cast<double>(static_cast<std::uint64_t>(Le(p, off, 8, false)));
}
float R4(std::string_view p, std::size_t off) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(Le(p, off, 4, false)));
}

gnss::ubx::RawxEpoch HandSetEpoch() {
  gnss::ubx::RawxEpoch e;
  e.rcv_tow_s = 288018.0001;
  e.week = 2422;
  e.leap_s = 18;
  e.leap_valid = true;
  gnss::ubx::RawxMeasurement a;
  a.pr_m = 21234567.891;
  a.cp_cycles = 111589123.456;
  a.do_hz = -1234.5;
  a.sv_id = 7;
  a.locktime_ms = 70000;  // saturates at 64500
  a.cno_dbhz = 44.4;
  a.pr_sigma_m = 0.3;         // 0.01 × 2^5 = 0.32
  a.cp_sigma_cycles = 0.016;  // 0.004 × 4
  a.do_sigma_hz = 0.02;       // 0.002 × 2^4 = 0.032
  gnss::ubx::RawxMeasurement b = a;
  b.sig_id = gnss::ubx::kSigGpsL2Cl;
  b.cp_valid = false;
  b.locktime_ms = 1500;
  e.meas = {a, b};
  return e;
}

TEST(ZedF9pRawx, FramingGolden) {
  const std::string f =
      gnss::ubx::Frame(gnss::ubx::kRxm, gnss::ubx::kRxmRawx, EncodeRxmRawx(HandSetEpoch()));
  hil::test::CheckOrWriteGolden(
      "vectors/gnss/zed_f9p_rxm_rawx.golden",
      "# RXM-RAWX of zed_f9p_rawx_test's hand-set epoch (UBX hex)\n" + Hex(f) + "\n");
}

TEST(ZedF9pRawx, FieldsAtTheirOffsets) {
  const std::string f =
      gnss::ubx::Frame(gnss::ubx::kRxm, gnss::ubx::kRxmRawx, EncodeRxmRawx(HandSetEpoch()));
  ASSERT_EQ(f.size(), 8U + 16 + 2 * 32);
  EXPECT_EQ(Le(f, 2, 1, false), 0x02);
  EXPECT_EQ(Le(f, 3, 1, false), 0x15);
  EXPECT_EQ(Le(f, 4, 2, false), 16 + 2 * 32);
  const std::string_view p = std::string_view(f).substr(6, 16 + 2 * 32);
  EXPECT_EQ(R8(p, 0), 288018.0001);
  EXPECT_EQ(Le(p, 8, 2, false), 2422);
  EXPECT_EQ(Le(p, 10, 1, true), 18);
  EXPECT_EQ(Le(p, 11, 1, false), 2);     // numMeas
  EXPECT_EQ(Le(p, 12, 1, false), 0x01);  // recStat: leapSec
  EXPECT_EQ(Le(p, 13, 1, false), 1);     // version
  const std::string_view m = p.substr(16, 32);
  EXPECT_EQ(R8(m, 0), 21234567.891);
  EXPECT_EQ(R8(m, 8), 111589123.456);
  EXPECT_EQ(R4(m, 16), -1234.5f);
  EXPECT_EQ(Le(m, 20, 1, false), 0);      // gnssId GPS
  EXPECT_EQ(Le(m, 21, 1, false), 7);      // svId
  EXPECT_EQ(Le(m, 22, 1, false), 0);      // sigId L1 C/A
  EXPECT_EQ(Le(m, 24, 2, false), 64500);  // locktime saturated
  EXPECT_EQ(Le(m, 26, 1, false), 44);     // cno
  EXPECT_EQ(Le(m, 27, 1, false), 5);      // prStdev 0.32 m
  EXPECT_EQ(Le(m, 28, 1, false), 4);      // cpStdev 0.016 cycles
  EXPECT_EQ(Le(m, 29, 1, false), 4);      // doStdev 0.032 Hz
  EXPECT_EQ(Le(m, 30, 1, false), 0x07);   // prValid, cpValid, halfCyc
  const std::string_view n = p.substr(48, 32);
  EXPECT_EQ(Le(n, 22, 1, false), 3);  // sigId L2 CL
  EXPECT_EQ(Le(n, 24, 2, false), 1500);
  EXPECT_EQ(Le(n, 30, 1, false), 0x01);  // no carrier: prValid only
}

// CFG-VALSET (RAM) of one U1 key from the host.
std::string Valset(std::uint32_t id, std::uint8_t value) {
  std::vector<std::uint8_t> p{0, 1, 0, 0};
  for (int k = 0; k < 4; ++k) p.push_back(static_cast<std::uint8_t>(id >> (8 * k)));
  p.push_back(value);
  return gnss::ubx::Frame(gnss::ubx::kCfg, gnss::ubx::kCfgValset, p);
}

int Count(const std::vector<SerialMessage>& sent, const std::string& name) {
  int n = 0;
  for (const SerialMessage& m : sent) n += m.name == name ? 1 : 0;
  return n;
}

TEST(ZedF9pRawx, OnlyWhenItsMessageRateIsSet) {
  ZedF9pDevice dev(test::RoverWithRadio(), 3);
  EXPECT_EQ(Count(test::RunUntil(dev, TimeFromSeconds(3.5)), "UBX-RXM-RAWX"), 0);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(3.5), Valset(key::kRxmRawxUart1, 1), out);
  ASSERT_EQ(Count(out.serial, "UBX-ACK-ACK"), 1);
  const auto sent = test::RunUntil(dev, TimeFromSeconds(8.5));
  EXPECT_EQ(Count(sent, "UBX-RXM-RAWX"), 5);  // 4 … 8 s
  for (const SerialMessage& m : sent) {
    if (m.name != "UBX-RXM-RAWX") continue;
    const std::string_view p = std::string_view(m.bytes).substr(6);
    const auto n = static_cast<std::size_t>(Le(p, 11, 1, false));
    EXPECT_GE(n, 2U * 6);  // at least 6 satellites on both signals
    EXPECT_EQ(Le(m.bytes, 4, 2, false), static_cast<std::int64_t>(16 + 32 * n));
  }
}

TEST(ZedF9pRawx, DoubleDifferencesWithTheBaseAreWholeCycles) {
  // the rover at the base's antenna (zero baseline): what the model adds cancels
  ZedF9pConfig c;
  const RtkBaseConfig b = test::KarajBase(rtcm3::MsmKind::kMsm7);
  c.start_utc = b.start_utc;
  c.flash = {{key::kRxmRawxUart1, 1}};
  ZedF9pDevice rover(c, 5);
  RtkBaseDevice base(b, 1);
  double worst_phase_cycles = 0, worst_code_m = 0;
  int dd = 0;
  DeviceOutput out;
  for (int k = 0; k < 60; ++k) {
    const Time t = TimeFromSeconds(k);
    base.EncodeEpoch(t);
    TruthSample truth = test::StillTruth(t);
    truth.lat_deg = b.lat_deg, truth.lon_deg = b.lon_deg, truth.height_m = b.height_m;
    rover.OnEvent(truth, out);
    out.clear();
    std::map<int, std::pair<double, double>> rover_l1;  // svid → code (m), phase (cycles)
    for (const auto& m : rover.last_rawx().meas) {
      if (m.sig_id == gnss::ubx::kSigGpsL1Ca) rover_l1[m.sv_id] = {m.pr_m, m.cp_cycles};
    }
    std::vector<std::pair<double, double>> sd;  // single differences rover − base
    constexpr double kL1_m = 299792458.0 / 1575.42e6;
    for (const auto& s : base.last_msm().satellites) {
      const auto r = rover_l1.find(s.id);
      if (r == rover_l1.end()) continue;
      sd.emplace_back(r->second.first - s.signals.front().pseudorange_m,
                      r->second.second - s.signals.front().phaserange_m / kL1_m);
    }
    ASSERT_GE(sd.size(), 5U);
    for (std::size_t i = 1; i < sd.size(); ++i) {
      const double phase = sd[i].second - sd[0].second;
      worst_phase_cycles = std::max(worst_phase_cycles, std::abs(phase - std::round(phase)));
      worst_code_m = std::max(worst_code_m, std::abs(sd[i].first - sd[0].first));
      ++dd;
    }
  }
  // phase: 3 + 2 mm noise and 4 mm multipath per receiver → a few hundredths of a cycle
  EXPECT_LT(worst_phase_cycles, 0.25);
  // code: 0.3 m noise scaled by elevation and 0.5 m multipath per receiver
  EXPECT_LT(worst_code_m, 10.0);
  RecordProperty("double_differences", dd);
  RecordProperty("worst_phase_dd_fraction_cycles", std::to_string(worst_phase_cycles));
}

}  // namespace
}  // namespace hil::rtk

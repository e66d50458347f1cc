// The fault campaign's injections: every link fault of the timeline (bit error rate, duplicate,
// truncate, baud mismatch, CAN reorder) applied deterministically and counted per fault, the
// host UART's view of a wrong baud, recovery times and navd's health object as the harness reads
// it.
#include <bitset>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/faults/fault_report.h"
#include "hil/harness/faults/uart_baud_mismatch.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {
namespace {

Scenario Parse(const std::string& faults) {
  return ParseScenario(
      "name: t\nduration_s: 100\norigin: {lat_deg: 35.4, lon_deg: 50.5, height_m: 1300}\n" + faults,
      "t.yaml");
}

SerialMessage Msg(double t_s, const std::string& bytes) {
  SerialMessage m;
  m.t_ready = TimeFromSeconds(t_s);
  m.bytes = bytes;
  return m;
}

std::size_t BitDiff(const std::string& a, const std::string& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += std::bitset<8>(static_cast<unsigned char>(a[i] ^ b[i])).count();
  return n;
}

TEST(BaudMismatchTest, EqualBaudsGiveTheBytesBack) {
  const std::string s = "$GPGGA,080000.00,3528.77,N*5A\r\n\x00\xff\x55";
  const BaudMismatchResult r = ReceiveAtWrongBaud(s, 9600, 9600);
  EXPECT_EQ(r.received, s);
  EXPECT_EQ(r.framing_errors, 0u);
}

TEST(BaudMismatchTest, AWrongBaudGivesGarbageAndFramingErrorsDeterministically) {
  const std::string s =
      "$GPRMC,080000.00,A,3528.77658,N,05035.87859,E,0.432,30.0,100613,,,A*6B\r\n";
  // the device at half the host's rate: each device bit spans two host bits
  const BaudMismatchResult slow = ReceiveAtWrongBaud(s, 4800, 9600);
  EXPECT_NE(slow.received, s);
  EXPECT_GT(slow.framing_errors, 0u);
  EXPECT_GT(slow.received.size(), s.size()) << "a slower sender looks like more, shorter bytes";
  EXPECT_EQ(slow.received.find("$GPRMC"), std::string::npos);
  // the device faster than the host: fewer bytes arrive than were sent
  const BaudMismatchResult fast = ReceiveAtWrongBaud(s, 19200, 9600);
  EXPECT_LT(fast.received.size(), s.size());
  EXPECT_EQ(ReceiveAtWrongBaud(s, 4800, 9600).received, slow.received);
  // 0x00 at half the rate: start + 8 zero bits span 18 host bits, so the stop bit samples low
  const BaudMismatchResult zero = ReceiveAtWrongBaud(std::string(1, '\0'), 4800, 9600);
  ASSERT_EQ(zero.received.size(), 1u);
  EXPECT_EQ(zero.received[0], '\0');
  EXPECT_EQ(zero.framing_errors, 1u);
}

TEST(ByteFaultsTest, BitErrorRateFlipsTheExpectedNumberOfBitsAndCountsThem) {
  const Scenario s =
      Parse("faults:\n  - {kind: byte_corruption, start_s: 10, end_s: 20, bit_error_rate: 1e-3}\n");
  FaultRecorder rec(s.faults);
  ByteFaultInjector inj(s.faults, 42, &rec);
  const std::string payload(1000, 'U');
  std::size_t flipped = 0;
  for (int k = 0; k < 100; ++k) {  // 800 000 bits
    SerialMessage m = Msg(10 + 0.05 * k, payload);
    ASSERT_TRUE(inj.Apply(m, "ttyGPS"));
    flipped += BitDiff(m.bytes, payload);
  }
  // Poisson with mean 800: 4 sigma is 113
  EXPECT_NEAR(static_cast<double>(flipped), 800.0, 113.0);
  ASSERT_EQ(rec.records().size(), 1u);
  EXPECT_EQ(rec.records()[0].count, flipped);
  EXPECT_EQ(rec.records()[0].unit, "bits flipped");
  EXPECT_DOUBLE_EQ(rec.records()[0].times_s.front(), 10.0);
  SerialMessage outside = Msg(25, payload);
  inj.Apply(outside, "ttyGPS");
  EXPECT_EQ(outside.bytes, payload);
}

TEST(ByteFaultsTest, DuplicateTruncateAndBaudMismatchAreAppliedAndCounted) {
  const Scenario s = Parse(
      "faults:\n"
      "  - {kind: frame_duplicate, start_s: 10, end_s: 20, probability: 1, link: ttyIMU}\n"
      "  - {kind: frame_truncate, start_s: 30, end_s: 40, probability: 1}\n"
      "  - {kind: baud_mismatch, start_s: 50, end_s: 60, baud: 4800, link: ttyGPS}\n");
  FaultRecorder rec(s.faults);
  ByteFaultInjector inj(s.faults, 1, &rec);
  const std::string payload = "$GPGGA,1,2,3,4,5,6,7,8,9*00\r\n";
  std::vector<SerialMessage> out;
  inj.Process(Msg(15, payload), "ttyGPS", 9600, out);
  ASSERT_EQ(out.size(), 1u) << "the duplicate fault is on ttyIMU only";
  out.clear();
  inj.Process(Msg(15, payload), "ttyIMU", 57600, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].bytes, payload);
  EXPECT_EQ(out[1].bytes, payload);
  out.clear();
  inj.Process(Msg(35, payload), "ttyGPS", 9600, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_LT(out[0].bytes.size(), payload.size());
  EXPECT_EQ(payload.rfind(out[0].bytes, 0), 0u) << "a truncated message is a prefix";
  out.clear();
  inj.Process(Msg(55, payload), "ttyGPS", 9600, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].bytes, ReceiveAtWrongBaud(payload, 4800, 9600).received);
  EXPECT_EQ(rec.records()[0].count, 1u);
  EXPECT_EQ(rec.records()[1].count, 1u);
  EXPECT_EQ(rec.records()[2].count, 1u);
  EXPECT_DOUBLE_EQ(rec.records()[2].times_s.at(0), 55.0);
}

TEST(ByteFaultsTest, CanReorderSwapsContentsAndKeepsBusTimesInOrder) {
  const Scenario s =
      Parse("faults:\n  - {kind: can_reorder, start_s: 10, end_s: 20, probability: 1}\n");
  FaultRecorder rec(s.faults);
  ByteFaultInjector inj(s.faults, 3, &rec);
  std::vector<CanFrame> frames(3);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    frames[i].t = TimeFromSeconds(12.0 + 0.001 * static_cast<double>(i));
    frames[i].id = 100 + static_cast<std::uint32_t>(i);
  }
  inj.ProcessCan(frames);
  EXPECT_EQ(frames[0].id, 101u);
  EXPECT_EQ(frames[1].id, 100u);
  EXPECT_EQ(frames[2].id, 102u);
  EXPECT_LT(frames[0].t, frames[1].t);
  EXPECT_EQ(rec.records()[0].count, 1u);
}

ErrorSample Err(double t, double h) {
  ErrorSample e;
  e.t = TimeFromSeconds(t);
  e.err_enu_m = Eigen::Vector3d(h, 0, 0);
  return e;
}

TEST(FaultReportTest, RecoveryTimeIsFromTheEndUntilTheErrorStaysBelowTheThreshold) {
  std::vector<ErrorSample> errs;
  for (int k = 0; k <= 400; ++k) {
    const double t = 0.1 * k;
    errs.push_back(Err(t, t >= 10 && t < 23 ? 3.0 : (t >= 24 && t < 24.5 ? 2.0 : 0.2)));
  }
  std::vector<FaultInjection> f(2);
  f[0].start_s = 10,
  f[0].end_s = 20;  // error high until 23 s, again 24-24.5 s: recovered at 24.5 s
  f[1].start_s = 30, f[1].end_s = 31;  // never left the threshold: 0
  ComputeRecoveryTimes(f, errs, 1.0);
  ASSERT_TRUE(f[0].recovery_time_s);
  EXPECT_NEAR(*f[0].recovery_time_s, 4.5, 1e-6);
  ASSERT_TRUE(f[1].recovery_time_s);
  EXPECT_NEAR(*f[1].recovery_time_s, 0.0, 1e-6);
  std::vector<ErrorSample> bad(errs.begin(),
                               errs.begin() + 150);  // the run ends at 14.9 s, in the fault
  ComputeRecoveryTimes(f, bad, 1.0);
  EXPECT_FALSE(f[0].recovery_time_s);
  std::map<std::string, std::optional<double>> table;
  AddFaultMetrics(table, f, EstimatorHealth{});
  EXPECT_FALSE(table.at("fault_recovery_time_s"))
      << "a fault that never recovered fails the criterion";
}

TEST(FaultReportTest, ReadsNavdHealthCountersAndEveryFlagRaised) {
  EstimatorHealth h;
  h.AddLine(R"({"tov_utc_s":1.0,"lat_deg":1,"mode":"ekf","status":0})");
  EXPECT_FALSE(h.present);
  h.AddLine(R"({"tov_utc_s":2.0,"health":{"flags":["mcu_reset"],"mcu_resets":1,"gnss_gaps":0}})");
  h.AddLine(R"({"tov_utc_s":3.0,"health":{"flags":[],"mcu_resets":1,"gnss_gaps":2}})");
  h.AddLine("{\"health\": not json");
  ASSERT_TRUE(h.present);
  EXPECT_EQ(h.counters.at("gnss_gaps"), 2.0);
  EXPECT_EQ(h.flags_seen.count("mcu_reset"), 1u);
  std::vector<FaultInjection> f(1);
  f[0].count = 3;
  f[0].recovery_time_s = 1.5;
  std::map<std::string, std::optional<double>> table;
  AddFaultMetrics(table, f, h);
  EXPECT_EQ(*table.at("navd.mcu_resets"), 1.0);
  EXPECT_EQ(*table.at("navd.flag.mcu_reset"), 1.0);
  EXPECT_EQ(*table.at("navd.flag.gnss_outage"), 0.0);
  EXPECT_EQ(*table.at("fault_injections_min"), 3.0);
  EXPECT_EQ(*table.at("fault_recovery_time_s"), 1.5);
  const nlohmann::json j = FaultInjectionsJson(f);
  EXPECT_EQ(j[0]["count"], 3);
}

}  // namespace
}  // namespace hil::harness

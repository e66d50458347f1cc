#include "hil/estimator/drivers/j1939_imu_decoder.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr int kLeap2013_s = 16;

// one line of a candump -l log: "(secs.micros) iface ID#HEX"
struct LogFrame {
  std::int64_t unix_ns = 0;
  CanRxFrame frame;
};

LogFrame ParseCandump(const std::string& line) {
  LogFrame out;
  const auto close = line.find(')');
  const std::string ts = line.substr(1, close - 1);
  const auto dot = ts.find('.');
  out.unix_ns =
      std::stoll(ts.substr(0, dot)) * 1000000000LL + std::stoll(ts.substr(dot + 1)) * 1000LL;
  const auto hash = line.find('#');
  const auto sp = line.rfind(' ', hash);
  out.frame.id =
      static_cast<std::uint32_t>(std::stoul(line.substr(sp + 1, hash - sp - 1), nullptr, 16));
  out.frame.extended = hash - sp - 1 == 8;
  const std::string hex = line.substr(hash + 1);
  out.frame.len = static_cast<std::uint8_t>(hex.size() / 2);
  for (std::size_t i = 0; i + 1 < hex.size() && i / 2 < 8; i += 2)
    out.frame.data[i / 2] = static_cast<std::uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16));
  out.frame.rx_ns = out.unix_ns;
  return out;
}

std::vector<std::string> ReadLines(const std::string& path, bool skip_comments) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || (skip_comments && line[0] == '#')) continue;
    out.push_back(line);
  }
  return out;
}

std::vector<double> CsvNumbers(const std::string& row) {
  std::vector<double> v;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');)
    v.push_back(std::strtod(cell.c_str(), nullptr));
  return v;
}

std::string VectorsCan() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return src ? std::string(src) + "/vectors/can/" : std::string();
}

CanRxFrame Frame(std::uint32_t id, std::array<std::uint8_t, 8> data, std::int64_t rx_ns,
                 std::uint8_t len = 8) {
  CanRxFrame f;
  f.id = id;
  f.data = data;
  f.len = len;
  f.rx_ns = rx_ns;
  return f;
}

TEST(J1939ImuDecoderTest, IdentifierParts) {
  const J1939Id a = ParseJ1939Id(0x0CF02AE2);
  EXPECT_EQ(a.priority, 3);
  EXPECT_EQ(a.pgn, kPgnAri);
  EXPECT_EQ(a.source, 0xE2);
  const J1939Id p = ParseJ1939Id(0x18EA55F9);  // PDU1 request to 0x55
  EXPECT_EQ(p.pgn, 0xEA00u);
  EXPECT_EQ(p.destination, 0x55);
}

// the worked examples of vectors/can/README.md
TEST(J1939ImuDecoderTest, ReadmeExamples) {
  const std::uint8_t ari[8] = {0x00, 0x7D, 0x00, 0x7D, 0x00, 0x82, 0xC0, 0x02};
  const auto a = DecodeAri(ari, 8);
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->pitch_rate_dps, 0.0);
  EXPECT_DOUBLE_EQ(a->roll_rate_dps, 0.0);
  EXPECT_DOUBLE_EQ(a->yaw_rate_dps, 10.0);
  EXPECT_DOUBLE_EQ(a->latency_s, 0.001);
  EXPECT_TRUE(a->available);
  const std::uint8_t accs[8] = {0x00, 0x7D, 0x00, 0x7D, 0xD5, 0x80, 0xC0, 0x02};
  const auto c = DecodeAccs(accs, 8);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->vertical_mps2, 9.81, 1e-9);
  EXPECT_NEAR(SpecificForceFlu_mps2(*c).z(), 9.81, 1e-9);
  const std::uint8_t ssi2[8] = {0x00, 0x00, 0x7D, 0x00, 0x00, 0x7D, 0x33, 0x02};
  const auto s = DecodeSsi2(ssi2, 8);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->pitch_deg, 0.0);
  EXPECT_DOUBLE_EQ(s->roll_deg, 0.0);
  EXPECT_EQ(s->pitch_compensation, 3);
  EXPECT_EQ(s->roll_compensation, 3);
  const std::uint8_t tp[8] = {0x40, 0x42, 0x0F, 0x00, 0x80, 0x51, 0x01, 0x6D};
  const auto t = DecodeHilTimePulse(tp, 8);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->tick, 1000000u);
  EXPECT_EQ(t->gps_tow_s, 86400u);
  EXPECT_EQ(t->gps_week_mod4096, 1744);
  EXPECT_TRUE(t->time_valid);
  EXPECT_FALSE(DecodeAri(ari, 7));
}

TEST(J1939ImuDecoderTest, AxesOfTheFluFrame) {
  AriMessage a;
  a.pitch_rate_dps = 2;  // nose up = −ω_y
  a.roll_rate_dps = 3;
  a.yaw_rate_dps = -4;
  const Eigen::Vector3d w = AngularRateFlu_radps(a);
  EXPECT_NEAR(w.x(), 3 * kDegToRad, 1e-15);
  EXPECT_NEAR(w.y(), -2 * kDegToRad, 1e-15);
  EXPECT_NEAR(w.z(), -4 * kDegToRad, 1e-15);
  AccsMessage c;
  c.lateral_mps2 = 1;
  c.longitudinal_mps2 = 2;
  c.vertical_mps2 = 3;
  EXPECT_EQ(SpecificForceFlu_mps2(c), Eigen::Vector3d(2, 1, 3));
}

// Golden: every frame of vectors/can/mcu_j1939.candump decodes to the engineering values of
// mcu_j1939.expected.csv within one LSB of its field.
TEST(J1939ImuDecoderTest, GoldenLogWithinOneLsb) {
  const auto log = ReadLines(VectorsCan() + "mcu_j1939.candump", false);
  const auto rows = ReadLines(VectorsCan() + "mcu_j1939.expected.csv", true);
  ASSERT_FALSE(log.empty());
  ASSERT_EQ(log.size(), rows.size());
  double worst_lsb[4] = {0, 0, 0, 0};  // ARI, ACCS, SSI2, pulse
  int counts[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < log.size(); ++i) {
    const LogFrame lf = ParseCandump(log[i]);
    const std::vector<double> v = CsvNumbers(rows[i]);
    ASSERT_GE(v.size(), 5u) << rows[i];
    EXPECT_EQ(lf.unix_ns, std::llround(v[0] * 1e6) * 1000) << log[i];
    const J1939Id id = ParseJ1939Id(lf.frame.id);
    ASSERT_EQ(id.pgn, static_cast<std::uint32_t>(v[2])) << log[i];
    EXPECT_EQ(id.source, 0xE2);
    const std::uint8_t* d = lf.frame.data.data();
    auto check = [&](int k, double got, double want, double lsb) {
      const double e = std::abs(got - want) / lsb;
      worst_lsb[k] = std::max(worst_lsb[k], e);
      EXPECT_LE(e, 1.0) << log[i] << " got " << got << " want " << want;
    };
    switch (id.pgn) {
      case kPgnAri: {
        const auto m = DecodeAri(d, 8);
        ASSERT_TRUE(m && m->available);
        check(0, m->pitch_rate_dps, v[3], 1.0 / 128);
        check(0, m->roll_rate_dps, v[4], 1.0 / 128);
        check(0, m->yaw_rate_dps, v[5], 1.0 / 128);
        EXPECT_DOUBLE_EQ(m->latency_s * 1e3, v[6]);
        ++counts[0];
        break;
      }
      case kPgnAccs: {
        const auto m = DecodeAccs(d, 8);
        ASSERT_TRUE(m && m->available);
        check(1, m->lateral_mps2, v[3], 0.01);
        check(1, m->longitudinal_mps2, v[4], 0.01);
        check(1, m->vertical_mps2, v[5], 0.01);
        EXPECT_DOUBLE_EQ(m->latency_s * 1e3, v[6]);
        ++counts[1];
        break;
      }
      case kPgnSsi2: {
        const auto m = DecodeSsi2(d, 8);
        ASSERT_TRUE(m && m->available);
        check(2, m->pitch_deg, v[3], 1.0 / 32768);
        check(2, m->roll_deg, v[4], 1.0 / 32768);
        EXPECT_DOUBLE_EQ(m->latency_s * 1e3, v[5]);
        ++counts[2];
        break;
      }
      case kPgnHilTimePulse: {
        const auto m = DecodeHilTimePulse(d, 8);
        ASSERT_TRUE(m && m->time_valid);
        check(3, m->tick, v[3], 1);
        check(3, m->gps_tow_s, v[4], 1);
        check(3, m->gps_week_mod4096, v[5], 1);
        ++counts[3];
        break;
      }
      default:
        ADD_FAILURE() << "unexpected PGN in " << log[i];
    }
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
  EXPECT_GT(counts[3], 0);
  std::printf(
      "worst decode error in LSB: ARI %.3f  ACCS %.3f  SSI2 %.3f  TIME_PULSE %.3f (frames "
      "%d/%d/%d/%d)\n",
      worst_lsb[0], worst_lsb[1], worst_lsb[2], worst_lsb[3], counts[0], counts[1], counts[2],
      counts[3]);
}

// The decoder turns the golden log (received at its emulated times) into IMU samples on GPS time:
// sample instants = frame time − latency, increments = trapezoid of the decoded rates.
TEST(J1939ImuDecoderTest, GoldenLogToImuSamplesOnGpsTime) {
  const auto log = ReadLines(VectorsCan() + "mcu_j1939.candump", false);
  const auto rows = ReadLines(VectorsCan() + "mcu_j1939.expected.csv", true);
  ASSERT_EQ(log.size(), rows.size());
  J1939ImuDecoder dec;
  std::vector<ImuSample> out;
  std::vector<std::int64_t> ari_unix_ns;
  std::vector<Eigen::Vector3d> rates;
  for (std::size_t i = 0; i < log.size(); ++i) {
    const LogFrame lf = ParseCandump(log[i]);
    const std::vector<double> v = CsvNumbers(rows[i]);
    if (static_cast<std::uint32_t>(v[2]) == kPgnAri) {
      ari_unix_ns.push_back(lf.unix_ns);
      rates.emplace_back(v[4] * kDegToRad, -v[3] * kDegToRad, v[5] * kDegToRad);
    }
    if (auto s = dec.Add(lf.frame)) out.push_back(*s);
  }
  const J1939ImuStats& st = dec.stats();
  EXPECT_EQ(st.other_source + st.unknown_pgn + st.bad_length + st.unpaired + st.not_available, 0u);
  EXPECT_EQ(st.pulses, 3u);
  EXPECT_GT(st.imu_no_time, 0u);  // the samples before the first pulse have no time
  ASSERT_GE(out.size(), 10u);
  EXPECT_EQ(out.size(), st.imu_out);
  // the MCU crystal (+37.5 ppm in the vector) from the latched ticks
  EXPECT_NEAR(dec.mcu_clock().offset_ppm(), 37.5, 2.0);
  const std::int64_t gps_minus_unix_ns = -(kGpsEpochUnix_s - kLeap2013_s) * kNsPerSecond;
  double worst_t_us = 0;
  for (const ImuSample& s : out) {
    // find the ARI of this sample: the one whose time − latency is nearest
    std::size_t k = 0;
    for (std::size_t j = 1; j < ari_unix_ns.size(); ++j) {
      if (std::llabs(ari_unix_ns[j] - 1000000 + gps_minus_unix_ns - ToNs(s.t)) <
          std::llabs(ari_unix_ns[k] - 1000000 + gps_minus_unix_ns - ToNs(s.t)))
        k = j;
    }
    ASSERT_GT(k, 0u);
    const double err_us =
        std::abs(static_cast<double>(ari_unix_ns[k] - 1000000 + gps_minus_unix_ns - ToNs(s.t))) *
        1e-3;
    worst_t_us = std::max(worst_t_us, err_us);
    EXPECT_LT(err_us, 100.0);
    EXPECT_NEAR(s.dt_s, 0.1, 1e-3);
    const Eigen::Vector3d expect = 0.5 * (rates[k - 1] + rates[k]) * s.dt_s;
    EXPECT_LT((s.delta_angle_B_rad - expect).norm(), 2 * (1.0 / 128) * kDegToRad * s.dt_s);
  }
  std::printf("IMU samples %zu, worst sample-time error %.1f us\n", out.size(), worst_t_us);
}

TEST(J1939ImuDecoderTest, FiltersSourceAddressAndCountsBadFrames) {
  const std::array<std::uint8_t, 8> ari = {0x00, 0x7D, 0x00, 0x7D, 0x00, 0x82, 0xC0, 0x02};
  J1939ImuDecoder dec;
  dec.Add(Frame(0x0CF02AE3, ari, 0));     // another source
  dec.Add(Frame(0x0CF004E2, ari, 0));     // EEC1, not ours
  dec.Add(Frame(0x0CF02AE2, ari, 0, 6));  // short
  CanRxFrame std_frame = Frame(0x123, ari, 0);
  std_frame.extended = false;
  dec.Add(std_frame);
  std::array<std::uint8_t, 8> na = ari;
  na[1] = 0xFE;  // error indicator
  dec.Add(Frame(0x0CF02AE2, na, 0));
  dec.Add(Frame(0x0CF02DE2, ari, 1000));  // ACCS without an ARI
  const J1939ImuStats& st = dec.stats();
  EXPECT_EQ(st.frames, 6u);
  EXPECT_EQ(st.other_source, 1u);
  EXPECT_EQ(st.unknown_pgn, 1u);
  EXPECT_EQ(st.bad_length, 1u);
  EXPECT_EQ(st.not_extended, 1u);
  EXPECT_EQ(st.not_available, 1u);
  EXPECT_EQ(st.unpaired, 1u);
  EXPECT_EQ(st.imu_out, 0u);

  J1939ImuDecoderConfig any;
  any.any_source = true;
  J1939ImuDecoder dec_any(any);
  dec_any.Add(Frame(0x0CF02AE3, ari, 0));
  EXPECT_EQ(dec_any.stats().other_source, 0u);
  EXPECT_EQ(dec_any.stats().ari, 1u);
}

// a synthetic stream: 100 Hz samples, 1 Hz pulses, a host clock running at `host_per_gps` (a scaled
// run) with an arbitrary offset, and an MCU reset in the middle
TEST(J1939ImuDecoderTest, ScaledHostClockAndMcuReset) {
  const double host_per_gps = 0.5;  // the run goes twice as fast as real time
  const std::int64_t host0 = 123456789000LL;
  const GpsTime gps0 = GpsTimeFromWeek(1744, 115200 * kNsPerSecond);
  auto host_of = [&](GpsTime g) {
    return host0 + static_cast<std::int64_t>(
                       std::llround(static_cast<double>((g - gps0).count()) * host_per_gps));
  };
  auto ari = [](double yaw_dps) {
    const auto raw = static_cast<std::uint32_t>(std::lround((yaw_dps + 250) * 128));
    return std::array<std::uint8_t, 8>{0x00,
                                       0x7D,
                                       0x00,
                                       0x7D,
                                       static_cast<std::uint8_t>(raw & 0xFF),
                                       static_cast<std::uint8_t>(raw >> 8),
                                       0xC0,
                                       0x02};
  };
  const std::array<std::uint8_t, 8> accs = {0x00, 0x7D, 0x00, 0x7D, 0xD5, 0x80, 0xC0, 0x02};
  J1939ImuDecoder dec;
  std::vector<ImuSample> out;
  std::uint32_t tick = 5000000;
  for (int ms = 0; ms < 6000; ms += 10) {
    const GpsTime t = gps0 + Nanoseconds{ms * 1000000LL +
                                         3000000};  // samples 3 ms after the whole millisecond grid
    if (ms % 1000 == 0) {
      if (ms == 3000) tick = 12345;  // MCU reset: the tick restarts
      const GpsTime edge = gps0 + Nanoseconds{ms * 1000000LL};
      const std::uint32_t tow = 115200 + static_cast<std::uint32_t>(ms / 1000);
      const std::uint64_t hi = tow | (1744ULL << 20);
      std::array<std::uint8_t, 8> tp{};
      for (int i = 0; i < 4; ++i) {
        tp[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(tick >> (8 * i));
        tp[static_cast<std::size_t>(4 + i)] = static_cast<std::uint8_t>(hi >> (8 * i));
      }
      dec.Add(Frame(0x0CFF50E2, tp, host_of(edge + Nanoseconds{1000000})));
      tick += 1000000;
    }
    const std::int64_t rx = host_of(t + Nanoseconds{1000000});
    if (auto s = dec.Add(Frame(0x0CF02AE2, ari(10.0), rx))) out.push_back(*s);
    if (auto s = dec.Add(Frame(0x0CF02DE2, accs, rx + 50000))) out.push_back(*s);
  }
  EXPECT_EQ(dec.stats().mcu_resets, 1u);
  EXPECT_NEAR(dec.arrival_clock().rate(), 1.0 / host_per_gps, 1e-6);
  ASSERT_GT(out.size(), 450u);
  for (const ImuSample& s : out) {
    const std::int64_t phase = ((s.t - gps0).count() - 3000000) % 10000000;
    EXPECT_LE(std::min<std::int64_t>(phase, 10000000 - phase), 1000) << (s.t - gps0).count();
    EXPECT_NEAR(s.dt_s, 0.01, 1e-6);
    EXPECT_NEAR(s.delta_angle_B_rad.z(), 10 * kDegToRad * 0.01, 1e-9);
    EXPECT_NEAR(s.delta_velocity_B_mps.z(), 9.81 * 0.01, 1e-9);
  }
}

TEST(ArrivalClockTest, TracksAndRestartsOnAJump) {
  ArrivalClock c;
  EXPECT_FALSE(c.ToGps(0));
  c.AddReference(1000 - 1000000000LL, GpsTimeFromNs(4 * kNsPerSecond));
  EXPECT_FALSE(c.ToGps(1000 - 1000000000LL));  // one reference does not give the rate
  for (int k = 0; k < 5; ++k)
    c.AddReference(1000 + k * 1000000000LL, GpsTimeFromNs(5 * kNsPerSecond + k * kNsPerSecond));
  EXPECT_EQ(*c.ToGps(1000 + 4500000000LL), GpsTimeFromNs(9500000000LL));
  c.AddReference(1000 + 5000000000LL, GpsTimeFromNs(20 * kNsPerSecond));  // GPS time jumps by 14 s
  EXPECT_EQ(c.jumps(), 1u);
  EXPECT_FALSE(c.ToGps(1000 + 5000000000LL));  // restarted: the rate is measured again
  c.AddReference(1000 + 6000000000LL, GpsTimeFromNs(21 * kNsPerSecond));
  EXPECT_EQ(*c.ToGps(1000 + 6500000000LL), GpsTimeFromNs(21500000000LL));
}

TEST(PeriodicSampleTimerTest, SmoothsJitterAndBridgesAMissedSample) {
  PeriodicSampleTimer timer;
  std::uint32_t state = 1;
  double worst = 0;
  for (int k = 0; k < 400; ++k) {
    if (k == 200) continue;  // a lost sample
    state = state * 1664525u + 1013904223u;
    const std::int64_t jitter = static_cast<std::int64_t>(state % 400000) - 200000;  // ±200 µs
    const GpsTime t = timer.Add(GpsTimeFromNs(k * 10000000LL + jitter));
    if (k > 100) worst = std::max(worst, std::abs(static_cast<double>(ToNs(t) - k * 10000000LL)));
  }
  EXPECT_LT(worst, 120000.0);  // smoothed well below the ±200 µs jitter
  EXPECT_NEAR(timer.period_ns(), 1e7, 2e3);
  EXPECT_EQ(timer.restarts(), 0u);
}

}  // namespace
}  // namespace hil::estimator::drivers

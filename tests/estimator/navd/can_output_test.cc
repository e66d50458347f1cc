// navd's NMEA 2000 output (estimator/navd/can_output.cc) through its candump log: the PGNs' rates
// agree with vectors/can/hil_imu.dbc (129026 every 250 ms, as NMEA 2000 says), and 129029 carries
// the satellites, HDOP and geoid separation the receiver reported, not literals (issue 15.4).
#include "can_output.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::navd {
namespace {

constexpr std::int64_t kT0UnixNs = 1370822400LL * 1000000000LL;  // 2013-06-10 00:00:00 UTC

struct LoggedFrame {
  double t_s = 0;
  std::uint32_t id = 0;
  std::vector<std::uint8_t> data;
  std::uint32_t pgn() const { return (id >> 8) & 0x3FFFF; }
};

// The log read back as can-utils writes it: "(secs.micros) iface IIIIIIII#HEX".
std::vector<LoggedFrame> ReadLog(const std::string& path) {
  std::vector<LoggedFrame> out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream ls(line);
    std::string ts, iface, frame;
    ls >> ts >> iface >> frame;
    LoggedFrame f;
    f.t_s = std::stod(ts.substr(1, ts.size() - 2));
    const std::size_t hash = frame.find('#');
    f.id = static_cast<std::uint32_t>(std::stoul(frame.substr(0, hash), nullptr, 16));
    for (std::size_t i = hash + 1; i + 1 < frame.size(); i += 2)
      f.data.push_back(static_cast<std::uint8_t>(std::stoi(frame.substr(i, 2), nullptr, 16)));
    out.push_back(f);
  }
  return out;
}

// 129029 payloads reassembled from their fast-packet frames (frame 0: sequence/index, length).
std::vector<std::vector<std::uint8_t>> GnssPositions(const std::vector<LoggedFrame>& frames) {
  std::vector<std::vector<std::uint8_t>> out;
  for (const LoggedFrame& f : frames) {
    if (f.pgn() != 129029) continue;
    if ((f.data[0] & 0x1F) == 0) {
      out.emplace_back(f.data.begin() + 2, f.data.end());
    } else {
      out.back().insert(out.back().end(), f.data.begin() + 1, f.data.end());
    }
  }
  for (auto& p : out) p.resize(43);
  return out;
}

std::int64_t Le(const std::vector<std::uint8_t>& p, int at, int n, bool is_signed) {
  std::uint64_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | p[static_cast<std::size_t>(at + i)];
  if (is_signed && n < 8 && (v >> (8 * n - 1)) & 1) v |= ~0ULL << (8 * n);
  return static_cast<std::int64_t>(v);
}

class CanOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("can_output_test_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    log_ = (dir_ / "n2k.candump").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Solutions at 100 Hz for `seconds` from kT0UnixNs + start_ms, with attitude.
  static void Publish(CanOutput& out, int start_ms, int seconds) {
    estimator::NavOutput o;
    o.valid = true;
    o.position = {35.79, 51.01, 1290.0};
    o.v_N_mps = Eigen::Vector3d(0.3, 0.3, 0);
    o.has_attitude = true;
    for (int k = 0; k < seconds * 100; ++k)
      out.Publish(o, kT0UnixNs + (start_ms + 10LL * k) * 1000000LL);
  }

  std::filesystem::path dir_;
  std::string log_;
};

TEST_F(CanOutputTest, RatesAgreeWithTheDbc) {
  {
    CanOutput out("", log_, 0x80, 10.0);
    Publish(out, 0, 4);
  }
  const std::vector<LoggedFrame> frames = ReadLog(log_);
  std::map<std::uint32_t, std::vector<double>> t_per_pgn;
  for (const LoggedFrame& f : frames) {
    if (f.pgn() == 129029 && (f.data[0] & 0x1F) != 0) continue;  // one time per packet
    t_per_pgn[f.pgn()].push_back(f.t_s);
  }
  // GenMsgCycleTime of hil_imu.dbc: 129025, 127250, 127257 100 ms; 129026 250 ms; 129029 1 s
  const std::map<std::uint32_t, double> period_s{
      {129025, 0.1}, {127250, 0.1}, {127257, 0.1}, {129026, 0.25}, {129029, 1.0}};
  for (const auto& [pgn, period] : period_s) {
    const std::vector<double>& t = t_per_pgn[pgn];
    ASSERT_EQ(t.size(), static_cast<std::size_t>(std::lround(4.0 / period))) << pgn;
    for (std::size_t i = 1; i < t.size(); ++i) {
      EXPECT_NEAR(t[i] - t[i - 1], period, 1e-6) << pgn;
    }
  }
  // every 129029 has the 129026 of its SID just before it (what the harness pairs them by)
  std::uint8_t last_cog_sog_sid = 0xFF;
  for (const LoggedFrame& f : frames) {
    if (f.pgn() == 129026) last_cog_sog_sid = f.data[0];
    if (f.pgn() == 129029 && (f.data[0] & 0x1F) == 0) {
      EXPECT_EQ(f.data[2], last_cog_sog_sid);
    }
  }
}

TEST_F(CanOutputTest, GnssPositionCarriesTheReceiversFigures) {
  {
    CanOutput out("", log_, 0x80, 10.0);
    Publish(out, 0, 1);  // before any fix: not available
    estimator::GnssSample g;
    g.num_sv = 9;
    g.hdop = 1.20;
    g.geoid_separation_m = -20.0;
    out.OnGnss(g);
    Publish(out, 1000, 1);
  }
  const auto p = GnssPositions(ReadLog(log_));
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(Le(p[0], 33, 1, false), 0xFF);             // number of SVs: not available
  EXPECT_EQ(Le(p[0], 34, 2, false), 0x7FFF);           // HDOP: not available
  EXPECT_EQ(Le(p[0], 38, 4, false), 0x7FFFFFFF);       // geoidal separation: not available
  EXPECT_EQ(Le(p[1], 33, 1, false), 9);                // the receiver's 9 satellites
  EXPECT_EQ(Le(p[1], 34, 2, true), 120);               // HDOP 1.20 (0.01)
  EXPECT_EQ(Le(p[1], 38, 4, true), -2000);             // −20.00 m (0.01 m)
  EXPECT_EQ(Le(p[1], 23, 8, true), 1290LL * 1000000);  // altitude: the solution's, ellipsoidal
}

}  // namespace
}  // namespace hil::navd

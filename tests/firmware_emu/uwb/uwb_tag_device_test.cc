// UwbTagDevice: the systematic field inverts eq. 8 exactly, the static accuracy before and after
// correction, NLOS bursts, Setting_Frame0 answers, the rate range, determinism, and the golden
// session of vectors/uwb (uwb_tag_session.bin / .expected.csv; HIL_REGEN_VECTORS=1 rewrites).
#include "hil/firmware_emu/uwb/uwb_tag_device.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/uwb/linktrack_setting_frame0.h"
#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"
#include "hil/firmware_emu/uwb/uwb_tdoa_frame.h"

namespace hil::uwb {
namespace {

TruthSample At(Time t, double x, double y) {
  TruthSample s;
  s.t = t;
  s.p_NB_N_m = {x, y, 0};
  return s;
}

Eigen::Vector2d Correct(const Eigen::Vector2d& m) {
  return m + Eigen::Vector2d(Paper003FieldX().Evaluate_m(m.x(), m.y()),
                             Paper003FieldY().Evaluate_m(m.x(), m.y()));
}

// Runs n fixes of a static tag and returns the device's last state.
Eigen::Vector2d MeanMeasured(UwbTagDevice& dev, const Eigen::Vector2d& p, int n) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  DeviceOutput out;
  for (int k = 0; k < n; ++k) {
    out.clear();
    dev.OnEvent(At(dev.next_event_time(), p.x(), p.y()), out);
    sum += dev.last_fix().p_W_measured_m;
  }
  return sum / n;
}

TEST(UwbTagDeviceTest, FieldAloneIsExactlyUndoneByEq8) {
  UwbTagConfig c;
  c.errors.white_sigma_m.setZero();
  c.errors.residual_sigma_m.setZero();
  UwbTagDevice dev(c, 1);
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(1.5, 3.5), Eigen::Vector2d(-2.61, -6.49),
                                   Eigen::Vector2d(-7, -7), Eigen::Vector2d(7.5, 7.5)}) {
    const Eigen::Vector2d m = MeanMeasured(dev, p, 1);
    EXPECT_NEAR((Correct(m) - p).norm(), 0.0, 1e-9);
    EXPECT_GT((m - p).norm(), 0.01);  // the field is there
  }
}

// Table 2's actual points, 100 fixes each (the paper's protocol), through eq. 8: mean |error|
// before ≈ the paper's 0.12 / 0.16 m, after ≈ the residual field's level (paper 0.04 / 0.05).
TEST(UwbTagDeviceTest, StaticAccuracyLikeTable3) {
  const double actual[20][2] = {{1.5, 3.5},     {1.5, -5.5},    {3.5, 1.5},    {3.5, -5.5},
                                {6.5, 1.5},     {-3.5, 3.5},    {-3.5, -5.5},  {-4.5, -5.5},
                                {-5.5, -1.5},   {-5.5, 5.0},    {6.13, 1.58},  {2.47, 5.39},
                                {1.22, -3.66},  {5.78, -2.32},  {-4.65, 5.81}, {-0.95, 1.43},
                                {-2.61, -6.49}, {-5.33, -4.53}, {-5.2, -1.3},  {-1.4, 2.7}};
  UwbTagDevice dev(UwbTagConfig{}, 7);
  Eigen::Vector2d before = Eigen::Vector2d::Zero(), after = Eigen::Vector2d::Zero();
  for (const auto& a : actual) {
    const Eigen::Vector2d p(a[0], a[1]);
    const Eigen::Vector2d m = MeanMeasured(dev, p, 100);
    before += (m - p).cwiseAbs() / 20.0;
    after += (Correct(m) - p).cwiseAbs() / 20.0;
  }
  std::printf("static mean |error| before X %.3f Y %.3f m, after X %.3f Y %.3f m\n", before.x(),
              before.y(), after.x(), after.y());
  EXPECT_NEAR(before.x(), 0.12, 0.04);
  EXPECT_NEAR(before.y(), 0.16, 0.05);
  EXPECT_LT(after.x(), 0.06);
  EXPECT_LT(after.y(), 0.08);
  EXPECT_LT(after.x(), 0.6 * before.x());
  EXPECT_LT(after.y(), 0.6 * before.y());
}

TEST(UwbTagDeviceTest, NlosBurstsLengthenOneRange) {
  UwbTagConfig c;
  c.errors.white_sigma_m.setZero();
  c.errors.residual_sigma_m.setZero();
  c.errors.nlos_zones.push_back({Eigen::Vector2d(0, 0), 2.0, 0.5, 1.0, 0.4, 0.0});
  UwbTagDevice dev(c, 3);
  DeviceOutput out;
  int bursts = 0;
  for (int k = 0; k < 50; ++k) {
    dev.OnEvent(At(dev.next_event_time(), 0.5, 0.2), out);
    const UwbFix& f = dev.last_fix();
    if (f.nlos.anchor < 0) continue;
    ++bursts;
    EXPECT_DOUBLE_EQ(f.nlos.bias_m, 0.4);
    EXPECT_GT((f.p_W_measured_m - Correct(f.p_W_measured_m)).norm(), 0.0);
  }
  EXPECT_GT(bursts, 10);
  EXPECT_EQ(dev.stats().nlos_fixes, static_cast<std::uint64_t>(bursts));
  // outside the zone: none
  UwbTagDevice far(c, 3);
  for (int k = 0; k < 50; ++k) far.OnEvent(At(far.next_event_time(), 6, 6), out);
  EXPECT_EQ(far.stats().nlos_fixes, 0u);
}

TEST(UwbTagDeviceTest, AnswersSettingReadRequestsAndCountsGarbage) {
  UwbTagDevice dev(UwbTagConfig{}, 1);
  DeviceOutput out;
  std::string req = linktrack::EncodeSettingReadRequest();
  EXPECT_EQ(static_cast<unsigned char>(req[127]), 0x55u);  // ArduPilot's request ends in 0x55
  std::string bad = req;
  bad[127] = 0x56;
  dev.OnHostBytes(0, TimeFromSeconds(1), "xy" + bad.substr(0, 60), out);
  dev.OnHostBytes(0, TimeFromSeconds(1), bad.substr(60) + req, out);
  ASSERT_EQ(out.serial.size(), 1u);
  const std::string& r = out.serial[0].bytes;
  ASSERT_EQ(r.size(), 128u);
  EXPECT_EQ(static_cast<unsigned char>(r[0]), 0x54u);
  EXPECT_EQ(static_cast<unsigned char>(r[1]), 0x00u);
  const auto i24 = [&](std::size_t at) {
    std::int32_t v = static_cast<unsigned char>(r[at]) |
                     static_cast<unsigned char>(r[at + 1]) << 8 |
                     static_cast<unsigned char>(r[at + 2]) << 16;
    return v & 0x800000 ? v - 0x1000000 : v;
  };
  EXPECT_EQ(i24(37), -10000);          // BS1 x
  EXPECT_EQ(i24(37 + 9 + 3), -10000);  // BS2 y
  EXPECT_EQ(i24(37 + 27 + 6), 1600);   // BS4 z
  EXPECT_EQ(i24(37 + 36), linktrack::kSettingNotAvailable);
  EXPECT_EQ(static_cast<unsigned char>(r[127]), linktrack::NlinkSum8(r.data(), 127));
  EXPECT_EQ(dev.stats().setting_replies, 1u);
  EXPECT_GT(dev.stats().host_garbage_bytes, 2u);
}

TEST(UwbTagDeviceTest, RateRangeAndCollinearAnchors) {
  UwbTagConfig c;
  c.rate_hz = 0.5;
  EXPECT_THROW(UwbTagDevice(c, 1), std::invalid_argument);
  c.rate_hz = 51;
  EXPECT_THROW(UwbTagDevice(c, 1), std::invalid_argument);
  c.rate_hz = 50;
  UwbTagDevice fast(c, 1);
  EXPECT_EQ(fast.next_event_time(), TimeFromNs(20000000));
  c.p_W_anchor_m[2] = {30, -10};
  EXPECT_THROW(UwbTagDevice(c, 1), std::invalid_argument);
}

std::string G(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", v + 0.0);
  return buf;
}

// A 2 s session at 5 Hz, both outputs, the tag driving north from A(−7, −7) at 0.5 m/s through an
// NLOS zone: the bytes, and the values they carry.
std::string Session(std::string& csv) {
  UwbTagConfig c;
  c.output = UwbOutput::kBoth;
  c.errors.nlos_zones.push_back({Eigen::Vector2d(-7, -6.5), 0.6, 0.5, 0.4, 0.3, 0.1});
  UwbTagDevice dev(c, 2024);
  std::string bin;
  std::ostringstream s;
  s << "# UWB tag session (vectors/uwb/README.md): per fix the values the frames carry.\n"
    << "# Generator: tests/firmware_emu/uwb/uwb_tag_device_test.cc (HIL_REGEN_VECTORS=1)\n"
    << "system_time_ms,true_x_m,true_y_m,x_m,y_m,r21_m,r31_m,r41_m,nlos_anchor\n";
  DeviceOutput out;
  for (int k = 0; k < 10; ++k) {
    out.clear();
    const Time t = dev.next_event_time();
    dev.OnEvent(At(t, -7.0, -7.0 + 0.5 * ToSeconds(t)), out);
    for (const SerialMessage& m : out.serial) bin += m.bytes;
    const UwbFix& f = dev.last_fix();
    s << ToNs(t) / 1000000 << "," << G(f.p_W_true_m.x()) << "," << G(f.p_W_true_m.y()) << ","
      << G(f.p_W_measured_m.x()) << "," << G(f.p_W_measured_m.y()) << "," << G(f.r_i1_m[0]) << ","
      << G(f.r_i1_m[1]) << "," << G(f.r_i1_m[2]) << "," << f.nlos.anchor << "\n";
  }
  csv = s.str();
  return bin;
}

TEST(UwbTagDeviceTest, GoldenSession) {
  std::string csv, csv2;
  const std::string bin = Session(csv);
  EXPECT_EQ(Session(csv2), bin);  // same seed, same bytes
  EXPECT_EQ(bin.size(), 10u * (128 + 24));
  const std::string dir = HIL_TEST_SOURCE_DIR "/vectors/uwb/";
  if (const char* r = std::getenv("HIL_REGEN_VECTORS"); r && std::string(r) == "1") {
    std::ofstream(dir + "uwb_tag_session.bin", std::ios::binary) << bin;
    std::ofstream(dir + "uwb_tag_session.expected.csv") << csv;
  }
  std::ifstream fb(dir + "uwb_tag_session.bin", std::ios::binary);
  std::ifstream fc(dir + "uwb_tag_session.expected.csv");
  std::stringstream sb, sc;
  sb << fb.rdbuf();
  sc << fc.rdbuf();
  EXPECT_EQ(sb.str(), bin) << "HIL_REGEN_VECTORS=1 rewrites";
  EXPECT_EQ(sc.str(), csv);
}

TEST(UwbTdoaFrameTest, FieldBytesByHand) {
  TdoaFrame f;
  f.id = 5;
  f.system_time_ms = 0x0A0B0C0D;
  f.t_i1_ps = {TdoaPicoseconds(0.3), TdoaPicoseconds(-3.0), 0};  // 1000 ps, −10000 ps
  const std::string b = EncodeTdoaFrame(f);
  ASSERT_EQ(b.size(), 24u);
  const auto u = [&](std::size_t i) {
    return static_cast<unsigned>(static_cast<unsigned char>(b[i]));
  };
  EXPECT_EQ(u(0), 0x55u);
  EXPECT_EQ(u(1), 0xD7u);
  EXPECT_EQ(u(2), 5u);
  EXPECT_EQ(u(3), 3u);
  EXPECT_EQ(u(4), 0x0Du);
  EXPECT_EQ(u(7), 0x0Au);
  EXPECT_EQ(u(8) | u(9) << 8, 1000u);      // 0x03E8
  EXPECT_EQ(u(12) | u(13) << 8, 0xD8F0u);  // −10000 = 0xFFFFD8F0
  EXPECT_EQ(u(15), 0xFFu);
  unsigned sum = 0;
  for (std::size_t i = 0; i < 23; ++i) sum += u(i);
  EXPECT_EQ(u(23), sum & 0xFFu);
}

}  // namespace
}  // namespace hil::uwb

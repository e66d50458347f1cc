// navd's several GNSS receivers: [input] gnss_device_N and [filter] antenna_N_m, validated against
// the mode, and the navigator's multi-receiver fusion with two to four antennas.
#include "hil/estimator/navd/navd_gnss_receivers.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/navd/navd_config.h"

namespace hil::estimator {
namespace {

NavdConfig Load(const std::string& text) {
  return NavdConfig::FromFile(ConfigFile::Parse(text, "navd.conf"));
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

constexpr const char* kThree =
    "[input]\n"
    "gnss_device = /r/ttyGPS\n"
    "gnss_device_1 = /r/ttyGPS1\n"
    "gnss_device_2 = /r/ttyGPS2\n"
    "[filter]\n"
    "mode = multi_gnss\n"
    "antenna_0_m = 3, 0, 0.5\n"
    "antenna_1_m = -1.5, 2.598, 0.5\n"
    "antenna_2_m = -1.5, -2.598, 0.5\n";

TEST(NavdGnssReceiversTest, ThreeReceiversGiveDevicesAndGeometry) {
  const NavdConfig c = Load(kThree);
  EXPECT_EQ(c.GnssDevices(), (std::vector<std::string>{"/r/ttyGPS", "/r/ttyGPS1", "/r/ttyGPS2"}));
  EXPECT_EQ(c.nav.multi_antenna_count, 3);
  EXPECT_DOUBLE_EQ(c.nav.multi_antenna_B_m(1, 1), 2.598);
  EXPECT_DOUBLE_EQ(c.nav.multi_antenna_B_m(2, 2), 0.5);
  EXPECT_DOUBLE_EQ(c.nav.multi_antenna_B_m(0, 0), 3.0);
}

TEST(NavdGnssReceiversTest, OneReceiverStaysAsBefore) {
  const NavdConfig c = Load("[input]\ngnss_device = /r/ttyGPS\n");
  EXPECT_EQ(c.GnssDevices(), (std::vector<std::string>{"/r/ttyGPS"}));
  EXPECT_TRUE(Load("[input]\ngnss_device =\n").GnssDevices().empty());
}

TEST(NavdGnssReceiversTest, ErrorsNameTheKey) {
  // several receivers outside multi_gnss
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_1 = b\n"),
            "navd.conf:3: [input] gnss_device_1: mode gnss_only reads one receiver; several need "
            "[filter] mode = multi_gnss");
  // a gap in the numbering
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_2 = c\n[filter]\nmode = multi_gnss\n"),
            "navd.conf:3: [input] gnss_device_2: receivers are numbered without gaps: [input] "
            "gnss_device_1 is missing");
  // beyond the limit, index 0 (that is gnss_device), twice, the same device twice
  EXPECT_EQ(ErrorOf("[input]\ngnss_device_4 = x\n"),
            "navd.conf:2: [input] gnss_device_4: receiver index out of range [1, 3] (gnss_device "
            "is receiver 0; navd reads at "
            "most 4 receivers)");
  EXPECT_NE(ErrorOf("[input]\ngnss_device_0 = x\n").find("out of range"), std::string::npos);
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_1 = b\ngnss_device_1 = c\n"),
            "navd.conf:4: [input] gnss_device_1: given twice (first on line 3)");
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_1 = a\n[filter]\nmode = multi_gnss\n"),
            "navd.conf:3: [input] gnss_device_1: 'a' is already [input] gnss_device");
  EXPECT_EQ(ErrorOf("[input]\ngnss_device_1 = b\n[filter]\nmode = multi_gnss\n"),
            "navd.conf:2: [input] gnss_device_1: needs [input] gnss_device (receiver 0)");
  // multi_gnss: antennas
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_1 = b\n[filter]\nmode = "
                    "multi_gnss\nantenna_0_m = 1, 0, 0\n"),
            "navd.conf:5: [filter] antenna_1_m: mode multi_gnss needs the antenna of every "
            "receiver (body frame x forward, y "
            "left, z up, metres)");
  EXPECT_EQ(
      ErrorOf("[input]\ngnss_device = a\n[filter]\nmode = multi_gnss\nantenna_0_m = 1, 0, 0\n"),
      "navd.conf:4: [filter] mode: mode multi_gnss needs at least two receivers ([input] "
      "gnss_device and gnss_device_1 …)");
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\n[filter]\nantenna_1_m = 1, 0, 0\n"),
            "navd.conf:4: [filter] antenna_1_m: there is no receiver 1 (1 configured)");
  EXPECT_EQ(ErrorOf("[filter]\nantenna_0_m = 1, 0\n"),
            "navd.conf:2: [filter] antenna_0_m: expected three comma-separated numbers 'x, y, z', "
            "got '1, 0'");
  EXPECT_NE(ErrorOf("[filter]\nantenna_0_m = 1, 0, 0, 4\n").find("expected three"),
            std::string::npos);
  EXPECT_NE(ErrorOf("[filter]\nantenna_0_m = 1, x, 0\n").find("expected three"), std::string::npos);
  EXPECT_NE(ErrorOf("[filter]\nantenna_4_m = 1, 0, 0\n").find("out of range [0, 3]"),
            std::string::npos);
  EXPECT_EQ(ErrorOf("[input]\ngnss_device = a\ngnss_device_1 = b\n[filter]\nmode = "
                    "multi_gnss\nantenna_0_m = 1, 0, 0\n"
                    "antenna_1_m = 1, 0.01, 2\n"),
            "navd.conf:6: [filter] antenna_0_m: the antennas must lie at least 5 cm from their "
            "centre horizontally to give a "
            "heading");
}

// The navigator's multi-receiver fusion for n antennas at arbitrary body positions.
void ExpectCentreAndHeading(int n) {
  NavigatorParams p;
  p.mode = NavMode::kMultiGnss;
  p.multi_antenna_count = n;
  for (int i = 0; i < n; ++i)
    p.multi_antenna_B_m.col(i) = Eigen::Vector3d(1.0 + 2.0 * i, 0.7 * i * i - 1.0, 0.4);
  Navigator nav(p);
  const LocalTangentFrame frame({35.4796096, 50.5979765, 1300});
  const Eigen::Vector3d origin(-4.0, 9.0, 0.0);
  const double yaw = -2.1;
  const Eigen::AngleAxisd R(yaw, Eigen::Vector3d::UnitZ());
  constexpr GpsTime kT = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
  for (int i = n - 1; i >= 0; --i) {
    EXPECT_FALSE(nav.Output().valid) << "no solution before every receiver has its fix";
    GnssSample g;
    g.t = kT;
    g.antenna = i;
    g.position = frame.ToLla(origin + R * p.multi_antenna_B_m.col(i));
    nav.Push(g);
  }
  const NavOutput o = nav.Output();
  ASSERT_TRUE(o.valid) << n;
  EXPECT_LT((frame.ToLocal(o.position) - origin).head<2>().norm(), 1e-6) << n;
  const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(std::atan2(x.y(), x.x()), yaw, 1e-6) << n;
  // a receiver index beyond the configured ones is bad input
  GnssSample bad;
  bad.antenna = n;
  bad.position = frame.ToLla(origin);
  nav.Push(bad);
  EXPECT_EQ(nav.stats().bad_input, 1u);
}

TEST(NavdGnssReceiversTest, NavigatorFusesTwoToFourReceivers) {
  for (int n = 2; n <= kMaxGnssAntennas; ++n) ExpectCentreAndHeading(n);
}

TEST(NavdGnssReceiversTest, NavigatorCombinesEpochsDeliveredInBurstsPerReceiver) {
  // GIVEN three receivers whose streams arrive one after the other, 20 epochs each (a host that
  // read one device's buffer at once), the first receiver's last epoch missing
  NavigatorParams p;
  p.mode = NavMode::kMultiGnss;
  for (int i = 0; i < 3; ++i) {
    const double a = i * 2 * M_PI / 3;
    p.multi_antenna_B_m.col(i) = Eigen::Vector3d(3 * std::cos(a), 3 * std::sin(a), 0);
  }
  Navigator nav(p);
  const LocalTangentFrame frame({35.4796096, 50.5979765, 1300});
  constexpr GpsTime kT = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
  std::vector<GpsTime> solutions;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 20; ++k) {
      if (i == 0 && k == 19) continue;
      GnssSample g;
      g.t = kT + k * std::chrono::seconds(1);
      g.antenna = i;
      g.position = frame.ToLla(Eigen::Vector3d(0.4 * k, 0, 0) + p.multi_antenna_B_m.col(i));
      nav.Push(g);
      const NavOutput o = nav.Output();
      if (o.valid && (solutions.empty() || solutions.back() != o.t)) solutions.push_back(o.t);
    }
  }
  // THEN every complete epoch gives one solution, in time order, at its own position
  ASSERT_EQ(solutions.size(), 19u);
  for (std::size_t k = 0; k < solutions.size(); ++k)
    EXPECT_EQ(solutions[k], kT + static_cast<std::int64_t>(k) * std::chrono::seconds(1));
  EXPECT_NEAR(frame.ToLocal(nav.Output().position).x(), 0.4 * 18, 1e-6);
}

}  // namespace
}  // namespace hil::estimator

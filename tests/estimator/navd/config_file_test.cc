#include "hil/estimator/navd/config_file.h"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "hil/estimator/navd/navd_config.h"

namespace hil::estimator {
namespace {

TEST(ConfigFileTest, ParsesSectionsKeysAndComments) {
  const auto cf = ConfigFile::Parse(
      "# c\n[input]\ngnss_device = /dev/ttyGPS  # the receiver\n\n[output]\njson=-\n", "t.conf");
  ASSERT_EQ(cf.entries().size(), 2u);
  EXPECT_EQ(cf.entries()[0].section, "input");
  EXPECT_EQ(cf.entries()[0].value, "/dev/ttyGPS");
  EXPECT_EQ(cf.entries()[1].line, 6);
  const NavdConfig c = NavdConfig::FromFile(cf);
  EXPECT_EQ(c.gnss_device, "/dev/ttyGPS");
}

TEST(ConfigFileTest, ErrorsNameFileLineAndKey) {
  try {
    NavdConfig::FromFile(ConfigFile::Parse("[input]\ngnss_baud = fast\n", "navd.conf"));
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "navd.conf:2: [input] gnss_baud: expected an integer, got 'fast'");
  }
  try {
    NavdConfig::FromFile(ConfigFile::Parse("[input]\n\ngnss_devcie = x\n", "navd.conf"));
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "navd.conf:3: [input] gnss_devcie: unknown key");
  }
  // a rate navd cannot open its device at is an error (it used to fall back to 9600 silently)
  try {
    NavdConfig::FromFile(
        ConfigFile::Parse("[input]\nimu_device = /x\nimu_baud = 14400\n", "n.conf"));
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(),
                 "n.conf:3: [input] imu_baud: unsupported baud rate 14400 (supported: 1200, 2400, "
                 "4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)");
  }
  EXPECT_THROW(ConfigFile::Parse("[input\n", "x"), ConfigError);
  EXPECT_THROW(ConfigFile::Load("/nonexistent/navd.conf"), ConfigError);
}

TEST(ConfigFileTest, ReferenceExampleIsValidAndComplete) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  const NavdConfig c = NavdConfig::FromFile(
      ConfigFile::Load(std::string(src) + "/estimator/navd/navd.conf.example"));
  EXPECT_EQ(c.mode(), NavMode::kEkf);
  EXPECT_EQ(c.imu_device, "/dev/ttyIMU");
  EXPECT_DOUBLE_EQ(c.nav.ekf.lever_arm_B_m.x(), 0.84);
  EXPECT_DOUBLE_EQ(c.nav.ekf.gnss_error_tau_s, 4.5);
  EXPECT_EQ(c.nav.fusion_horizon, Nanoseconds{300'000'000});
  EXPECT_TRUE(c.nmea_device.empty());
}

// A [filter] switch that is on by default: the empty section leaves it on, "KEY = false" turns it
// off, and a value that is not a boolean is a ConfigError naming it.
template <typename Switch>
void ExpectOnByDefaultSwitch(const std::string& key, Switch on_in) {
  SCOPED_TRACE(key);
  EXPECT_TRUE(on_in(NavdConfig::FromFile(ConfigFile::Parse("[filter]\n", "n.conf")).nav));
  EXPECT_FALSE(on_in(
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\n" + key + " = false\n", "n.conf")).nav));
  EXPECT_THROW(NavdConfig::FromFile(ConfigFile::Parse("[filter]\n" + key + " = 1\n", "n.conf")),
               ConfigError);
}

// issue 41: the IMU noise check; issue 39: the NHC's premise checked from its innovations (the
// walker), the NMEA velocity's σ learned from its innovations, the fading after a gap in the
// gap's noise
TEST(ConfigFileTest, RobustnessSwitchesAreOnByDefault) {
  ExpectOnByDefaultSwitch("imu_noise_check", [](const auto& nav) { return nav.imu_noise.enabled; });
  ExpectOnByDefaultSwitch("nhc_noise_check", [](const auto& nav) { return nav.nhc_noise.enabled; });
  ExpectOnByDefaultSwitch("gnss_velocity_noise",
                          [](const auto& nav) { return nav.gnss_vel_noise.enabled; });
  ExpectOnByDefaultSwitch("fade_gap_noise",
                          [](const auto& nav) { return nav.robust.fade_gap_noise; });
}

// issues 39/41: the IMU's mounting pitch is estimated (prior σ 2°), its yaw held, unless
// [filter] mount_angle_estimation = false; mount_pitch_std_deg / mount_yaw_std_deg set the priors
TEST(ConfigFileTest, MountAngleKeys) {
  const EkfParams def = NavdConfig::FromFile(ConfigFile::Parse("[filter]\n", "n.conf")).nav.ekf;
  EXPECT_TRUE(def.estimate_mount_angles);
  EXPECT_NEAR(def.mount_pitch_std_rad, 2.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_EQ(def.mount_yaw_std_rad, 0.0);
  const EkfParams set =
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nmount_angle_estimation = false\n"
                                             "mount_pitch_std_deg = 0.5\nmount_yaw_std_deg = 1\n",
                                             "n.conf"))
          .nav.ekf;
  EXPECT_FALSE(set.estimate_mount_angles);
  EXPECT_NEAR(set.mount_pitch_std_rad, 0.5 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(set.mount_yaw_std_rad, 1.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_THROW(
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nmount_angle_estimation = 1\n", "n.conf")),
      ConfigError);
}

// issue 41: the vibration-widened vehicle model is off unless [filter] vibration_tau_s > 0
TEST(ConfigFileTest, VibrationTauKey) {
  EXPECT_EQ(NavdConfig::FromFile(ConfigFile::Parse("[filter]\n", "n.conf")).nav.vibration_tau_s,
            0.0);
  EXPECT_DOUBLE_EQ(
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nvibration_tau_s = 0.5\n", "n.conf"))
          .nav.vibration_tau_s,
      0.5);
  EXPECT_THROW(
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nvibration_tau_s = -1\n", "n.conf")),
      ConfigError);
}

TEST(ConfigFileTest, ReceiverConfigurationKeys) {
  const NavdConfig on = NavdConfig::FromFile(ConfigFile::Parse(
      "[input]\ngnss_protocol = ubx\ngnss_configure = true\ngnss_rate_hz = 4\n", "n.conf"));
  EXPECT_TRUE(on.gnss_configure);
  EXPECT_DOUBLE_EQ(on.gnss_rate_hz, 4.0);
  EXPECT_FALSE(NavdConfig::FromFile(ConfigFile::Parse("[input]\n", "n.conf")).gnss_configure)
      << "off by default";
  try {
    NavdConfig::FromFile(ConfigFile::Parse("[input]\ngnss_configure = yes\n", "n.conf"));
    ADD_FAILURE() << "accepted 'yes'";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "n.conf:2: [input] gnss_configure: expected true or false");
  }
  try {
    NavdConfig::FromFile(ConfigFile::Parse("[input]\ngnss_rate_hz = 50\n", "n.conf"));
    ADD_FAILURE() << "accepted 50 Hz";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "n.conf:2: [input] gnss_rate_hz: value 50 out of range [0, 10]");
  }
}

TEST(ConfigFileTest, FilterSchemaErrorsAreClear) {
  const auto err = [](const std::string& text) {
    try {
      NavdConfig::FromFile(ConfigFile::Parse(text, "n.conf"));
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nmode = gnss_only\n", "n.conf")).mode(),
      NavMode::kGnssOnly);
  EXPECT_EQ(err("[filter]\nmode = kalman\n"),
            "n.conf:2: [filter] mode: unknown mode 'kalman' (known: ekf, planar2d, gnss_only, "
            "imu_only, multi_gnss)");
  EXPECT_EQ(err("[filter]\nmode = ekf\n"),
            "n.conf:2: [filter] mode: mode ekf needs [input] imu_device");
  EXPECT_EQ(err("[filter]\nlever_arm_m = 1, 2\n"),
            "n.conf:2: [filter] lever_arm_m: expected three comma-separated numbers 'x, y, z', got "
            "'1, 2'");
  EXPECT_EQ(err("[filter]\nnhc_std_mps = -1\n"),
            "n.conf:2: [filter] nhc_std_mps: value -1 out of range [0, 10]");
  EXPECT_EQ(err("[input]\nimu_format = razor\n"),
            "n.conf:2: [input] imu_format: unknown IMU format 'razor' (known: mcu, razor_text)");
}

}  // namespace
}  // namespace hil::estimator

namespace hil::estimator {
namespace {

TEST(ConfigFileTest, NmeaUereSetsTheAccuracyOfNmeaFixes) {
  EXPECT_DOUBLE_EQ(NavdConfig{}.nmea_uere_m, 2.5);
  const NavdConfig c =
      NavdConfig::FromFile(ConfigFile::Parse("[filter]\nnmea_uere_m = 0.5\n", "n.conf"));
  EXPECT_DOUBLE_EQ(c.nmea_uere_m, 0.5);
  try {
    NavdConfig::FromFile(ConfigFile::Parse("[filter]\nnmea_uere_m = 0\n", "n.conf"));
    FAIL() << "a zero UERE must be refused";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("n.conf:2: [filter] nmea_uere_m"), std::string::npos)
        << e.what();
  }
}

TEST(ConfigFileTest, RtkNmeaAccuracyFloatModelAndGnssWait) {
  const NavdConfig c = NavdConfig::FromFile(ConfigFile::Parse(
      "[filter]\nnmea_uere_m = 0.5\nnmea_rtk_fixed_std_m = 0.008\nnmea_rtk_float_std_m = 0.2\n"
      "nmea_velocity_std_mps = 0.1\ngnss_error_tau_s = 30\ngnss_error_std_m = 0.008\n"
      "gnss_float_error_tau_s = 5\ngnss_float_error_std_m = 0.2\nfusion_horizon_s = "
      "0.25\ngnss_max_latency_s = 2.5\n",
      "n.conf"));
  EXPECT_DOUBLE_EQ(NmeaHorizontalStd(c.nmea_accuracy(), kGgaQualityRtkFixed, 0.9), 0.008);
  EXPECT_DOUBLE_EQ(NmeaHorizontalStd(c.nmea_accuracy(), kGgaQualityRtkFloat, 0.9), 0.2);
  EXPECT_NEAR(NmeaHorizontalStd(c.nmea_accuracy(), 1, 1.2), 1.2 * 0.5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(NmeaHorizontalStd(c.nmea_accuracy(), 1, std::nullopt), 5.0 * 0.5 / std::sqrt(2.0),
              1e-12);
  EXPECT_DOUBLE_EQ(c.nmea_accuracy().velocity_std_mps, 0.1);
  EXPECT_DOUBLE_EQ(c.nav.ekf.gnss_float_error_tau_s, 5.0);
  EXPECT_DOUBLE_EQ(c.nav.ekf.gnss_float_error_std_m, 0.2);
  EXPECT_EQ(c.nav.gnss_max_latency, Nanoseconds{2'500'000'000});
  // without RTK settings a quality-4 fix falls back to HDOP × UERE
  EXPECT_NEAR(NmeaHorizontalStd(NmeaAccuracy{}, kGgaQualityRtkFixed, 1.0), 2.5 / std::sqrt(2.0),
              1e-12);
  const auto err = [](const std::string& text) {
    try {
      NavdConfig::FromFile(ConfigFile::Parse(text, "n.conf"));
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(err("[filter]\nfusion_horizon_s = 0.5\ngnss_max_latency_s = 0.3\n")
                .find("n.conf:3: [filter] gnss_max_latency_s"),
            std::string::npos);
  EXPECT_NE(
      err("[filter]\ngnss_error_tau_s = 30\ngnss_error_std_m = 0.01\ngnss_float_error_tau_s = 5\n")
          .find("gnss_float_error_std_m"),
      std::string::npos);
  EXPECT_NE(err("[filter]\ngnss_float_error_tau_s = 5\ngnss_float_error_std_m = 0.2\n")
                .find("gnss_error_tau_s"),
            std::string::npos);
  EXPECT_NE(
      err("[filter]\nnmea_rtk_fixed_std_m = 0\n").find("n.conf:2: [filter] nmea_rtk_fixed_std_m"),
      std::string::npos);
  EXPECT_NE(err("[filter]\ngnss_max_latency_s = 9\n").find("out of range"), std::string::npos);
  const NavdConfig sp = NavdConfig::FromFile(
      ConfigFile::Parse("[filter]\nspeed_rw = 0.0005\nspeed_dev_std_mps = 0.02\n", "n.conf"));
  EXPECT_DOUBLE_EQ(sp.nav.ekf.speed_rw_mps_rthz, 0.0005);
  EXPECT_DOUBLE_EQ(sp.nav.ekf.speed_dev_std_mps, 0.02);
  EXPECT_NE(err("[filter]\nspeed_dev_std_mps = 0\n").find("n.conf:2: [filter] speed_dev_std_mps"),
            std::string::npos);
}

}  // namespace
}  // namespace hil::estimator

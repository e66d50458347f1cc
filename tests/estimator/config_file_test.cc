#include "hil/estimator/config_file.h"

#include <gtest/gtest.h>

#include "hil/estimator/navd_config.h"

namespace hil::estimator {
namespace {

TEST(ConfigFileTest, ParsesSectionsKeysAndComments) {
  const auto cf = ConfigFile::Parse("# c\n[input]\ngnss_device = /dev/ttyGPS  # the receiver\n\n[output]\njson=-\n", "t.conf");
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
  EXPECT_THROW(ConfigFile::Parse("[input\n", "x"), ConfigError);
  EXPECT_THROW(ConfigFile::Load("/nonexistent/navd.conf"), ConfigError);
}

}  // namespace
}  // namespace hil::estimator

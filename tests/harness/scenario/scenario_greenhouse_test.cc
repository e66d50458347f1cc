// The `greenhouse:` scenario section: values reach the world configuration, and layouts that
// make no sense fail with the file, line and field.
#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kMinimal =
    "name: t\n"
    "origin: {lat_deg: 32.0, lon_deg: 118.8}\n";

void ExpectError(const std::string& text, int line, const std::string& field,
                 const std::string& fragment) {
  try {
    ParseScenario(text, "g.yaml");
    FAIL() << "expected a ScenarioError for:\n" << text;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "g.yaml");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ScenarioGreenhouse, ReadsEveryField) {
  const Scenario s =
      ParseScenario(Joined(kMinimal,
                           "greenhouse:\n"
                           "  ridges: {count: 5, width_m: 0.7, height_m: 0.25, "
                           "spacing_m: 1.7, length_m: 40, first_start_enu_m: [2, 3], "
                           "direction_deg: 0}\n"
                           "  headland_m: 4\n"
                           "  side_margin_m: 1.2\n"
                           "  wall_height_m: 2.8\n"
                           "  posts: {spacing_m: 5, size_m: 0.12, height_m: 2.5}\n"),
                    "g.yaml");
  ASSERT_TRUE(s.greenhouse);
  const world::GreenhouseConfig& c = *s.greenhouse;
  EXPECT_EQ(c.ridge_count, 5);
  EXPECT_DOUBLE_EQ(c.ridge_width_m, 0.7);
  EXPECT_DOUBLE_EQ(c.ridge_height_m, 0.25);
  EXPECT_DOUBLE_EQ(c.ridge_spacing_m, 1.7);
  EXPECT_DOUBLE_EQ(c.ridge_length_m, 40);
  EXPECT_DOUBLE_EQ(c.first_ridge_start_N_m.y(), 3);
  EXPECT_DOUBLE_EQ(c.row_direction_deg, 0);
  EXPECT_DOUBLE_EQ(c.headland_m, 4);
  EXPECT_DOUBLE_EQ(c.side_margin_m, 1.2);
  EXPECT_DOUBLE_EQ(c.wall_height_m, 2.8);
  EXPECT_DOUBLE_EQ(c.post_spacing_m, 5);
  EXPECT_DOUBLE_EQ(c.post_size_m, 0.12);
  EXPECT_DOUBLE_EQ(c.post_height_m, 2.5);
  EXPECT_FALSE(ParseScenario(kMinimal, "g.yaml").greenhouse);
}

TEST(ScenarioGreenhouse, OverlappingRidgesNameTheSpacing) {
  ExpectError(Joined(kMinimal,
                     "greenhouse:\n"
                     "  ridges:\n"
                     "    width_m: 1.0\n"
                     "    spacing_m: 0.9\n"),
              6, "greenhouse.ridges.spacing_m", "must exceed ridge_width_m");
  // the spacing is the default (1.8 m): the width is the key that is there, but the spacing is
  // the field at fault
  ExpectError(Joined(kMinimal, "greenhouse:\n  ridges: {width_m: 2.0}\n"), 4, "greenhouse.ridges",
              "spacing_m (default)");
}

TEST(ScenarioGreenhouse, PostsWiderThanTheMarginAndUnknownKeys) {
  ExpectError(Joined(kMinimal,
                     "greenhouse:\n"
                     "  side_margin_m: 0.2\n"
                     "  posts:\n"
                     "    size_m: 0.3\n"),
              6, "greenhouse.posts.size_m", "side margin");
  ExpectError(Joined(kMinimal, "greenhouse:\n  ridges: {widht_m: 1}\n"), 4,
              "greenhouse.ridges.widht_m", "did you mean 'width_m'");
  ExpectError(Joined(kMinimal, "greenhouse:\n  ridges: {count: 0}\n"), 4, "greenhouse.ridges.count",
              "out of range");
}

}  // namespace
}  // namespace hil::harness

namespace hil::harness {
namespace {

TEST(ScenarioRangeSensors, DefaultsAndTheLibraryLayout) {
  const Scenario s = ParseScenario(Joined(kMinimal,
                                          "greenhouse: {}\n"
                                          "rangefinders: {rate_hz: 50, format: mm}\n"
                                          "lidar: {rotation_hz: 10, mount_m: [0, 0, 0.5]}\n"),
                                   "g.yaml");
  ASSERT_TRUE(s.rangefinders.enabled);
  ASSERT_EQ(s.rangefinders.units.size(), 4u);
  EXPECT_EQ(s.rangefinders.units[0].link, "ttyRF_RF");
  EXPECT_DOUBLE_EQ(s.rangefinders.units[1].mount.x_m, -0.2);
  EXPECT_DOUBLE_EQ(s.rangefinders.units[3].mount.yaw_deg, 90);
  EXPECT_EQ(s.rangefinders.module.settings.frame_rate_hz, 50);
  EXPECT_EQ(s.rangefinders.module.settings.format, rangefinder::OutputFormat::kMm9Byte);
  ASSERT_TRUE(s.lidar.enabled);
  EXPECT_DOUBLE_EQ(s.lidar.config.rotation_hz, 10);
  EXPECT_DOUBLE_EQ(s.lidar.config.mount.z_m, 0.5);
  const Scenario lib =
      ParseScenario(Joined(kMinimal, "include: [greenhouse/seed001_greenhouse.yaml]\n"), "g.yaml");
  ASSERT_TRUE(lib.greenhouse);
  EXPECT_EQ(lib.greenhouse->ridge_count, 4);
  EXPECT_EQ(lib.rangefinders.units.size(), 4u);
  EXPECT_EQ(lib.lidar.link, "ttyLIDAR");
}

TEST(ScenarioRangeSensors, BadSensorSections) {
  ExpectError(Joined(kMinimal, "rangefinders: {}\n"), 3, "rangefinders", "needs a greenhouse");
  ExpectError(Joined(kMinimal, "greenhouse: {}\nrangefinders: {baud: 12345}\n"), 4,
              "rangefinders.baud", "TF-Luna manual");
  ExpectError(Joined(kMinimal,
                     "greenhouse: {}\n"
                     "rangefinders:\n"
                     "  units:\n"
                     "    - {name: a, link: ttyA}\n"
                     "    - {name: b, link: ttyA}\n"),
              7, "rangefinders.units[1].link", "two units");
  ExpectError(Joined(kMinimal, "greenhouse: {}\nlidar: {rotation_hz: 30}\n"), 4,
              "lidar.rotation_hz", "out of range");
}

}  // namespace
}  // namespace hil::harness

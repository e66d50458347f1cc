// The scenario keys of a rough GNSS (issue 41): `obstructions:`, `gnss.multipath`, `gnss.rtk`;
// every bad value names its file, line and field.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

constexpr const char* kBase = "name: t\norigin: {lat_deg: 45.75, lon_deg: 126.63}\n";

TEST(ScenarioGnssRoughTest, WithoutTheKeysNothingChanges) {
  const Scenario s = ParseScenario(Joined(kBase, "gnss: {profile: rtk}\n"), "s.yaml");
  EXPECT_FALSE(s.gnss.shading.active());
  EXPECT_FALSE(s.gnss.rtk_rough);
}

TEST(ScenarioGnssRoughTest, ObstructionsMultipathAndRtkAreRead) {
  const Scenario s = ParseScenario(
      Joined(kBase,
             "obstructions:\n"
             "  - {kind: tree_line, from_m: [0, 10], to_m: [300, 10], width_m: 6, height_m: 15,\n"
             "     loss_db_per_m: 1.5}\n"
             "  - {kind: building, centre_m: [50, -30], size_m: [20, 12], heading_deg: 90,"
             " height_m: 8}\n"
             "gnss:\n"
             "  profile: rtk\n"
             "  multipath: {nav_min_dbhz: 25, correlator_spacing_chip: 0.1}\n"
             "  rtk: {time_to_fix_s: 30, wrong_fix_probability: 0.2, min_sats_fixed: 7}\n"),
      "s.yaml");
  ASSERT_TRUE(s.gnss.shading.active());
  const auto& obs = s.gnss.shading.obstructions->obstacles();
  ASSERT_EQ(obs.size(), 2u);
  EXPECT_EQ(obs[0].kind, world::SkyObstacleKind::kTreeLine);
  EXPECT_NEAR(obs[0].footprint.centre_m.x(), 150.0, 1e-12);
  EXPECT_NEAR(obs[0].footprint.half_extent_m.x(), 150.0, 1e-12);
  EXPECT_NEAR(obs[0].footprint.half_extent_m.y(), 3.0, 1e-12);
  EXPECT_EQ(obs[0].loss_db_per_m, 1.5);
  EXPECT_EQ(obs[0].reflection_amplitude, 0.2);  // the kind's default
  EXPECT_TRUE(obs[1].opaque);
  EXPECT_NEAR(obs[1].footprint.heading_rad, std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(s.gnss.shading.nav_min_dbhz, 25.0);
  EXPECT_EQ(s.gnss.shading.correlator_spacing_chip, 0.1);
  ASSERT_TRUE(s.gnss.rtk_rough);
  EXPECT_EQ(s.gnss.rtk_rough->time_to_fix_s, 30.0);
  EXPECT_EQ(s.gnss.rtk_rough->wrong_fix_probability, 0.2);
  EXPECT_EQ(s.gnss.rtk_rough->min_sats_fixed, 7);
}

TEST(ScenarioGnssRoughTest, AGreenhouseTakesTheGreenhouseSectionsWalls) {
  const Scenario s = ParseScenario(Joined(kBase,
                                          "greenhouse: {ridges: {count: 4, length_m: 30}}\n"
                                          "obstructions: [{kind: greenhouse}]\n"),
                                   "s.yaml");
  const auto& o = s.gnss.shading.obstructions->obstacles().at(0);
  EXPECT_EQ(o.height_m, s.greenhouse->wall_height_m);
  // 30 m ridges + 2 × 3 m headland along the rows
  EXPECT_NEAR(2 * o.footprint.half_extent_m.x(), 36.0, 1e-9);
  EXPECT_EQ(o.loss_db, 3.0);
}

void ExpectError(const std::string& text, int line, const std::string& field) {
  try {
    ParseScenario(Joined(kBase, text), "s.yaml");
    FAIL() << "expected a ScenarioError for\n" << text;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("s.yaml:" + std::to_string(line) + ": ", 0), 0u)
        << e.what();
  }
}

TEST(ScenarioGnssRoughTest, BadValuesNameFileLineAndField) {
  ExpectError("obstructions:\n  - {kind: hedge, height_m: 3}\n", 4, "obstructions[0].kind");
  ExpectError("obstructions:\n  - {kind: tree_line, from_m: [0, 0], to_m: [10, 0]}\n", 4,
              "obstructions[0].height_m");
  ExpectError("obstructions:\n  - {kind: tree_line, from_m: [0, 0], to_m: [0, 0], height_m: 3}\n",
              4, "obstructions[0].to_m");
  ExpectError(
      "obstructions:\n  - {kind: building, centre_m: [0, 0], size_m: [5, 5], height_m: 3,"
      " loss_db: 3}\n",
      4, "obstructions[0].loss_db");
  ExpectError(
      "obstructions:\n  - {kind: tree_line, from_m: [0, 0], to_m: [9, 0], height_m: 3,"
      " reflection_amplitude: 2}\n",
      4, "obstructions[0].reflection_amplitude");
  ExpectError("obstructions:\n  - {kind: greenhouse}\n", 4, "obstructions[0].kind");
  // a footprint without its points (used to read past an empty list: a crash)
  ExpectError("obstructions:\n  - {kind: tree_line, height_m: 3}\n", 4, "obstructions[0].centre_m");
  ExpectError("obstructions:\n  - {kind: tree_line, from_m: [0, 0], height_m: 3}\n", 4,
              "obstructions[0].to_m");
  ExpectError("obstructions:\n  - {kind: building, centre_m: [0, 0], height_m: 3}\n", 4,
              "obstructions[0].size_m");
  ExpectError("gnss:\n  multipath: {track_min_dbhz: 25, nav_min_dbhz: 20}\n", 4,
              "gnss.multipath.nav_min_dbhz");
  ExpectError("gnss:\n  rtk: {time_to_fix_s: 5}\n", 4, "gnss.rtk");
  ExpectError("gnss:\n  profile: rtk\n  rtk: {wrong_fix_probability: 1.5}\n", 5,
              "gnss.rtk.wrong_fix_probability");
  ExpectError("gnss:\n  profile: rtk\n  rtk: {min_sats_fixed: 3}\n", 5, "gnss.rtk.min_sats_fixed");
  ExpectError("gnss:\n  profile: rtk\n  rtk: {time_to_fx_s: 3}\n", 5, "gnss.rtk.time_to_fx_s");
}

}  // namespace
}  // namespace hil::harness

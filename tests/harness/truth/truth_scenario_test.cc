// The scenario sections of the truth (origin, vehicle, path, terrain, vibration, truth): every
// shape and model loads, and bad values are reported with file, line and field.
#include <cmath>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

std::string Doc(const std::string& body) {
  return "name: t\norigin: {lat_deg: 35.0, lon_deg: 50.0}\n" + body;  // body starts on line 3
}

void ExpectError(const std::string& text, int line, const std::string& field,
                 const std::string& fragment) {
  try {
    ParseScenario(text, "s.yaml");
    FAIL() << "expected a ScenarioError for:\n" << text;
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(TruthScenarioTest, LegacyLineKeysStillWork) {
  const Scenario s =
      ParseScenario(Doc("vehicle: {model: bicycle, wheelbase_m: 1.2, speed_lag_s: 0.3}\n"
                        "path: {type: line, start_enu_m: [1, 2], heading_deg: 30, speed_kmh: 1.6, "
                        "steer_deg: 5}\n"),
                    "s.yaml");
  EXPECT_DOUBLE_EQ(s.truth.vehicle.wheelbase_m, 1.2);
  EXPECT_DOUBLE_EQ(s.truth.vehicle.speed_lag_s, 0.3);
  EXPECT_EQ(*s.truth.start_p_N_m, Eigen::Vector2d(1, 2));
  EXPECT_DOUBLE_EQ(*s.truth.heading_deg, 30);
  EXPECT_NEAR(s.truth.speed_mps, 1.6 / 3.6, 1e-12);
  EXPECT_DOUBLE_EQ(s.truth.steer_deg, 5);
  EXPECT_FALSE(s.truth.path.has_value());
}

TEST(TruthScenarioTest, Seed003RectangleOnTheGreenhousePlatform) {
  const Scenario s = ParseScenario(Doc("vehicle: {model: bicycle}\n"
                                       "path: {type: rectangle, speed_mps: 0.5, lookahead_m: 2}\n"),
                                   "s.yaml");
  ASSERT_TRUE(s.truth.path);
  EXPECT_EQ(s.truth.path->vertices().front().p_N_m, Eigen::Vector2d(-7, -7));
  EXPECT_TRUE(s.truth.path->vertices()[1].p_N_m.isApprox(Eigen::Vector2d(-7, 8)));
  EXPECT_DOUBLE_EQ(s.truth.vehicle.wheelbase_m, 0.84);
  EXPECT_DOUBLE_EQ(s.truth.vehicle.track_m, 0.55);
  EXPECT_DOUBLE_EQ(s.truth.vehicle.max_steer_deg, 32);
}

TEST(TruthScenarioTest, Seed004TractorFieldWithRoughGroundAndVibration) {
  const Scenario s =
      ParseScenario(Doc("vehicle: {model: tractor}\n"
                        "path: {type: boustrophedon, row_length_m: 170, row_spacing_m: 7.5, rows: "
                        "10, speed_mps: 1}\n"
                        "terrain: {type: rough, amplitude_m: 0.03, waves: 6, seed: 3}\n"
                        "vibration:\n"
                        "  components:\n"
                        "    - {frequency_hz: 30, heave_accel_mps2: 0.8, roll_rate_dps: 1.5}\n"
                        "truth: {earth_rotation: false, rtol: 1.0e-9}\n"),
                    "s.yaml");
  ASSERT_TRUE(s.truth.path);
  EXPECT_NEAR(s.truth.path->length_m(), 10 * 170 + 9 * (M_PI * 3.75), 1.0);
  EXPECT_DOUBLE_EQ(s.truth.guidance.lookahead_m, 3.0);
  EXPECT_EQ(s.truth.terrain.type, truth::TerrainConfig::Type::kRough);
  EXPECT_EQ(s.truth.terrain.waves, 6);
  ASSERT_EQ(s.truth.vibration.components.size(), 1u);
  const double w = 2 * M_PI * 30;
  EXPECT_NEAR(s.truth.vibration.components[0].heave_m * w * w, 0.8, 1e-12);
  EXPECT_FALSE(s.truth.earth_rotation);
  EXPECT_DOUBLE_EQ(s.truth.rtol, 1e-9);
}

TEST(TruthScenarioTest, DiffDriveWaypointsWithStopsAndSpeeds) {
  const Scenario s = ParseScenario(Doc("vehicle: {model: diff_drive, track_m: 0.5}\n"
                                       "path:\n"
                                       "  type: waypoints\n"
                                       "  points:\n"
                                       "    - [0, 0]\n"
                                       "    - {enu_m: [0, 10], stop_s: 5, speed_mps: 0.3}\n"
                                       "    - [10, 10]\n"),
                                   "s.yaml");
  EXPECT_EQ(s.truth.vehicle.model, truth::VehicleParams::Model::kDiffDrive);
  ASSERT_TRUE(s.truth.path);
  EXPECT_DOUBLE_EQ(s.truth.path->vertices()[1].stop_s, 5);
  EXPECT_DOUBLE_EQ(*s.truth.path->vertices()[1].speed_mps, 0.3);
  const Scenario spin = ParseScenario(
      Doc("vehicle: {model: diff_drive}\npath: {type: line, speed_mps: 0, yaw_rate_dps: 20}\n"),
      "s.yaml");
  EXPECT_DOUBLE_EQ(spin.truth.yaw_rate_dps, 20);
}

TEST(TruthScenarioTest, AbLineCircleAndSpeedProfileLoad) {
  const Scenario a = ParseScenario(
      Doc("path: {type: ab_line, a_enu_m: [0, 0], b_enu_m: [10, 0], start_enu_m: [0, 1]}\n"),
      "s.yaml");
  EXPECT_TRUE(a.truth.path->direction(0).isApprox(Eigen::Vector2d(1, 0)));
  const Scenario c =
      ParseScenario(Doc("path:\n  type: circle\n  radius_m: 4\n  laps: 2\n  speed_profile:\n"
                        "    - {t_s: 10, speed_mps: 0}\n    - {t_s: 15, speed_kmh: 1.8}\n"),
                    "s.yaml");
  ASSERT_EQ(c.truth.speed_profile.size(), 2u);
  EXPECT_DOUBLE_EQ(c.truth.speed_profile[1].speed_mps, 0.5);
  EXPECT_NEAR(c.truth.path->length_m(), 2 * 2 * M_PI * 4, 0.01);
}

TEST(TruthScenarioTest, BadValuesNameFileLineAndField) {
  ExpectError(Doc("vehicle: {model: hovercraft}\n"), 3, "vehicle.model",
              "unknown value 'hovercraft'");
  ExpectError(Doc("vehicle: {model: diff_drive, wheelbase_m: 1}\n"), 3, "vehicle.wheelbase_m",
              "not a parameter");
  ExpectError(Doc("path: {type: line, steer_deg: 40}\n"), 3, "path.steer_deg", "out of range");
  ExpectError(Doc("path: {type: rectangle, a_enu_m: [0, 0]}\n"), 3, "path.a_enu_m", "unknown key");
  ExpectError(Doc("path:\n  type: waypoints\n  points: [[0, 0]]\n"), 5, "path.points",
              "at least 2 waypoints");
  ExpectError(Doc("path:\n  type: waypoints\n  points:\n    - [0, 0]\n    - [0, 0]\n"), 7,
              "path.points[1]", "repeats");
  ExpectError(Doc("vehicle: {model: tractor}\npath: {type: boustrophedon, turn_radius_m: 2}\n"), 4,
              "path.turn_radius_m", "minimum turning radius");
  ExpectError(Doc("vehicle: {model: tractor}\npath: {type: boustrophedon, row_spacing_m: 5}\n"), 4,
              "path.row_spacing_m", "at least twice the turn radius");
  ExpectError(Doc("path:\n  type: line\n  speed_profile:\n    - {t_s: 5, speed_mps: 1}\n    - "
                  "{t_s: 5, speed_mps: 2}\n"),
              7, "path.speed_profile[1].t_s", "must increase");
  ExpectError(Doc("terrain: {type: plane, amplitude_m: 0.1}\n"), 3, "terrain.amplitude_m",
              "unknown key");
  ExpectError(Doc("terrain: {type: rough, min_wavelength_m: 10, max_wavelength_m: 5}\n"), 3,
              "terrain.max_wavelength_m", "must not be below");
  ExpectError(Doc("vibration:\n  components:\n    - {heave_accel_mps2: 1}\n"), 5,
              "vibration.components[0]", "frequency_hz");
  ExpectError(Doc("truth: {rtol: 0.1}\n"), 3, "truth.rtol", "out of range");
  ExpectError(Doc("vehicle: {model: diff_drive}\npath: {type: line, steer_deg: 3}\n"), 4,
              "path.steer_deg", "unknown key");
}

}  // namespace
}  // namespace hil::harness

// The scenario reference cannot drift: docs/scenario_reference.md is what `hil scenario-keys`
// prints from the tables the reader validates with, every table is well formed, and the reader
// refuses what its table refuses (a key it does not list, a number outside its range, a value
// not among a choice's). A key read but not in its table does not compile: the test
// scenario_key_missing_does_not_compile builds scenario_key_missing.cc and expects it to fail.
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario_keys.h"

#include "joined_text.h"

namespace hil::harness {
namespace {

using hil::test::Joined;

std::string SourceDir() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return src ? src : ".";
}

TEST(ScenarioReferenceTest, TheCommittedReferenceIsTheGeneratedOne) {
  const std::string path = SourceDir() + "/docs/scenario_reference.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::stringstream committed;
  committed << in.rdbuf();
  EXPECT_EQ(committed.str(), ScenarioReference())
      << path << " differs from the scenario reader's tables: regenerate it with\n"
      << "  build-ci/bin/hil scenario-keys > docs/scenario_reference.md";
}

TEST(ScenarioReferenceTest, EveryTableIsWellFormed) {
  std::set<std::string_view> paths;
  for (const KeySection* s : ScenarioKeyTables()) {
    SCOPED_TRACE(std::string(s->path));
    EXPECT_TRUE(paths.insert(s->path).second) << "two tables for one section";
    EXPECT_FALSE(s->meaning.empty());
    std::set<std::string_view> names;
    for (const ScenarioKey& k : s->keys) {
      SCOPED_TRACE(std::string(k.name));
      EXPECT_TRUE(names.insert(k.name).second) << "a key listed twice";
      EXPECT_FALSE(k.meaning.empty());
      EXPECT_FALSE(k.default_text.empty());
      if (k.type == KeyType::kNumber || k.type == KeyType::kInteger) {
        EXPECT_LT(k.lo, k.hi);
      }
      EXPECT_EQ(k.type == KeyType::kChoice, !k.choices.empty());
    }
  }
}

// A figure the reader defaults to says where it comes from (a source, or "ours: REASON"). The
// sections listed are those whose rows all say so; the older tables are being filled in.
TEST(ScenarioReferenceTest, EveryFigureOfTheSourcedSectionsNamesItsSource) {
  const std::set<std::string_view> sourced{"vehicle", "closed_loop.actuator (serial_base)"};
  std::size_t checked = 0;
  for (const KeySection* s : ScenarioKeyTables()) {
    if (!sourced.contains(s->path)) continue;
    for (const ScenarioKey& k : s->keys) {
      const bool figure = (k.type == KeyType::kNumber || k.type == KeyType::kInteger) &&
                          k.default_text.find_first_of("0123456789") != std::string_view::npos;
      if (!figure) continue;
      ++checked;
      EXPECT_FALSE(k.source.empty()) << s->path << "." << k.name << " = " << k.default_text;
    }
  }
  EXPECT_EQ(checked, 11U + 8U);  // vehicle's 11 figures, the base's 8 (its slip is a point)
}

constexpr const char* kBase = "name: t\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765}\n";

// The message of the error loading `text` ("" when it loads).
std::string ErrorOf(const std::string& text) {
  try {
    ParseScenario(text, "t.yaml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioReferenceTest, TheReaderTakesItsTablesRangesAndChoices) {
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {model: skid_steer, icr_expansion: 0.9}\n")),
            "t.yaml:3: vehicle.icr_expansion: value 0.9 out of range [1, 4]");
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {model: diff_drive, icr_offset_m: 0.1}\n")),
            "t.yaml:3: vehicle.icr_offset_m: only a parameter of the skid_steer model");
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {model: skid_steer, wheelbase_m: 1}\n")),
            "t.yaml:3: vehicle.wheelbase_m: not a parameter of the skid_steer model");
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {model: skidsteer}\n")),
            "t.yaml:3: vehicle.model: unknown value 'skidsteer' (one of: bicycle tractor "
            "diff_drive skid_steer)");
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {icr_expansoin: 2}\n")),
            "t.yaml:3: vehicle.icr_expansoin: unknown key (did you mean 'icr_expansion'?)");
  EXPECT_EQ(ErrorOf("name: t\norigin: {lat_deg: 35, lon_deg: 50, height_m: 9001}\n"),
            "t.yaml:2: origin.height_m: value 9001 out of range [-500, 9000]");
  EXPECT_EQ(ErrorOf(Joined(kBase, "closed_loop: {actuator: {}}\n")),
            "t.yaml:3: closed_loop.channel: the serial base protocol drives a vehicle of model "
            "diff_drive "
            "or skid_steer");
  EXPECT_EQ(ErrorOf(Joined(kBase, "vehicle: {model: skid_steer, icr_expansion: 2}\n")), "");
  const Scenario s =
      ParseScenario(Joined(kBase, "vehicle: {model: skid_steer, icr_expansion: 2}\n"), "t.yaml");
  EXPECT_EQ(s.truth.vehicle.model, truth::VehicleParams::Model::kSkidSteer);
  EXPECT_EQ(s.truth.vehicle.icr_expansion, 2.0);
  EXPECT_EQ(s.truth.vehicle.icr_offset_m, 0.05);  // the preset's
}

}  // namespace
}  // namespace hil::harness

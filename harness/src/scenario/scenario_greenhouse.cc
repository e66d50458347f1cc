// The `greenhouse:` section: paper 001's ridge map (hil::world::GreenhouseConfig). Every size is
// a scenario parameter (the paper gives none, seeds_001_003.md A.14); a layout that makes no
// sense fails with the file, line and field.
#include <array>
#include <cstdint>
#include <string>

#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kGreenhouseSectionKeys{"greenhouse"};

namespace greenhouse_keys {  // named: the unity build joins the readers' files

using enum KeyType;

inline constexpr ScenarioKey kGreenhouse[] = {
    {"ridges", kMapping, "", "the defaults below", 0, 0, "the ridges (greenhouse.ridges)"},
    {"headland_m", kNumber, "m", "3", 0, 1000,
     "clear ground between the ridge ends and the end walls"},
    {"side_margin_m", kNumber, "m", "1.5", 0, 1000,
     "clear ground between the outer ridges and the side walls"},
    {"wall_height_m", kNumber, "m", "3", 0.1, 50, "the walls' height"},
    {"posts", kMapping, "", "the defaults below", 0, 0,
     "posts along the inside of the side walls (greenhouse.posts)"},
};

inline constexpr ScenarioKey kRidges[] = {
    {"count", kInteger, "", "4", 1, 200, "ridges; aisle k lies between ridges k and k+1"},
    {"width_m", kNumber, "m", "0.6", 0.05, 20, "a ridge's width"},
    {"height_m", kNumber, "m", "0.3", 0.01, 5, "a ridge's height above the aisle floor"},
    {"spacing_m", kNumber, "m", "1.8", 0.1, 50,
     "centre to centre; must exceed the width (aisle = spacing − width)"},
    {"length_m", kNumber, "m", "30", 0.5, 2000, "along the rows"},
    {"first_start_enu_m", kPoint, "m", "[0, 0]", 0, 0, "ridge 0's centre-line start [east, north]"},
    {"direction_deg", kNumber, "deg", "90", -360, 360,
     "the rows' direction, counter-clockwise from east; further ridges lie to the left"},
};

inline constexpr ScenarioKey kPosts[] = {
    {"spacing_m", kNumber, "m", "4", 0, 1000, "along the side walls (0: no posts)"},
    {"size_m", kNumber, "m", "0.1", 0.01, 5, "square section (≤ side_margin_m)"},
    {"height_m", kNumber, "m", "3", 0.1, 50, "height"},
};

}  // namespace greenhouse_keys

extern const KeySection kGreenhouseSection{
    "greenhouse", "paper 001's ridge map, which the range sensors see and the aisles score",
    greenhouse_keys::kGreenhouse};
extern const KeySection kRidgesSection{"greenhouse.ridges", "the ridges", greenhouse_keys::kRidges};
extern const KeySection kPostsSection{"greenhouse.posts", "the posts", greenhouse_keys::kPosts};

namespace {

using greenhouse_keys::kGreenhouse;
using greenhouse_keys::kPosts;
using greenhouse_keys::kRidges;

void ReadRidges(const YamlReader& y, world::GreenhouseConfig& c) {
  const KeyedReader<kRidges> r(y);
  r.CheckKeys();
  c.ridge_count = static_cast<int>(r.Integer("count", c.ridge_count));
  c.ridge_width_m = r.Number("width_m", c.ridge_width_m);
  c.ridge_height_m = r.Number("height_m", c.ridge_height_m);
  c.ridge_spacing_m = r.Number("spacing_m", c.ridge_spacing_m);
  c.ridge_length_m = r.Number("length_m", c.ridge_length_m);
  c.row_direction_deg = r.Number("direction_deg", c.row_direction_deg);
  const std::vector<double> p = r.Doubles("first_start_enu_m", 2, {0, 0});
  c.first_ridge_start_N_m = {p[0], p[1]};
}

void ReadPosts(const YamlReader& y, world::GreenhouseConfig& c) {
  const KeyedReader<kPosts> r(y);
  r.CheckKeys();
  c.post_spacing_m = r.Number("spacing_m", c.post_spacing_m);
  c.post_size_m = r.Number("size_m", c.post_size_m);
  c.post_height_m = r.Number("height_m", c.post_height_m);
}

// Where each GreenhouseConfig field is read: 0 the section itself, 1 `ridges:`, 2 `posts:`.
struct FieldKey {
  const char* field;
  int section;
  const char* key;
};
constexpr FieldKey kFieldKeys[] = {
    {"ridge_count", 1, "count"},          {"ridge_width_m", 1, "width_m"},
    {"ridge_height_m", 1, "height_m"},    {"ridge_spacing_m", 1, "spacing_m"},
    {"ridge_length_m", 1, "length_m"},    {"post_spacing_m", 2, "spacing_m"},
    {"post_size_m", 2, "size_m"},         {"post_height_m", 2, "height_m"},
    {"headland_m", 0, "headland_m"},      {"side_margin_m", 0, "side_margin_m"},
    {"wall_height_m", 0, "wall_height_m"}};

[[noreturn]] void FailAt(const world::ConfigProblem& problem,
                         const std::array<const YamlReader*, 3>& sections) {
  for (const FieldKey& f : kFieldKeys) {
    if (problem.field != f.field) continue;
    const YamlReader* r = sections[static_cast<std::size_t>(f.section)];
    if (r != nullptr && r->Has(f.key)) r->Fail(f.key, problem.message);
    // a default value is at fault: name the section that would hold the key
    if (r != nullptr) r->Fail(std::string(f.key) + " (default): " + problem.message);
  }
  sections[0]->Fail(problem.field + ": " + problem.message);
}

}  // namespace

void ReadGreenhouseSection(const YamlReader& root, Scenario& s) {
  const std::optional<YamlReader> g = root.OptionalChild("greenhouse");
  if (!g) return;
  const KeyedReader<kGreenhouse> r(*g);
  r.CheckKeys();
  world::GreenhouseConfig c;
  const std::optional<YamlReader> ridges = r.OptionalChild("ridges");
  const std::optional<YamlReader> posts = r.OptionalChild("posts");
  if (ridges) ReadRidges(*ridges, c);
  if (posts) ReadPosts(*posts, c);
  c.headland_m = r.Number("headland_m", c.headland_m);
  c.side_margin_m = r.Number("side_margin_m", c.side_margin_m);
  c.wall_height_m = r.Number("wall_height_m", c.wall_height_m);
  if (const auto problem = world::CheckGreenhouse(c)) {
    FailAt(*problem, {&*g, ridges ? &*ridges : nullptr, posts ? &*posts : nullptr});
  }
  s.greenhouse = c;
}

}  // namespace hil::harness

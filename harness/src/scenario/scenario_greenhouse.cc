// The `greenhouse:` section: paper 001's ridge map (hil::world::GreenhouseConfig). Every size is
// a scenario parameter (the paper gives none, seeds_001_003.md A.14); a layout that makes no
// sense fails with the file, line and field.
#include <array>
#include <cstdint>
#include <string>

#include "scenario_sections.h"

namespace hil::harness {

const std::vector<std::string> kGreenhouseSectionKeys{"greenhouse"};

namespace {

void ReadRidges(const YamlReader& r, world::GreenhouseConfig& c) {
  r.CheckKeys({"count", "width_m", "height_m", "spacing_m", "length_m", "first_start_enu_m",
               "direction_deg"});
  c.ridge_count = static_cast<int>(r.Int("count", c.ridge_count, 1, 200));
  c.ridge_width_m = r.DoubleIn("width_m", c.ridge_width_m, 0.05, 20);
  c.ridge_height_m = r.DoubleIn("height_m", c.ridge_height_m, 0.01, 5);
  c.ridge_spacing_m = r.DoubleIn("spacing_m", c.ridge_spacing_m, 0.1, 50);
  c.ridge_length_m = r.DoubleIn("length_m", c.ridge_length_m, 0.5, 2000);
  c.row_direction_deg = r.DoubleIn("direction_deg", c.row_direction_deg, -360, 360);
  const std::vector<double> p = r.Doubles("first_start_enu_m", 2, {0, 0});
  c.first_ridge_start_N_m = {p[0], p[1]};
}

void ReadPosts(const YamlReader& r, world::GreenhouseConfig& c) {
  r.CheckKeys({"spacing_m", "size_m", "height_m"});
  c.post_spacing_m = r.DoubleIn("spacing_m", c.post_spacing_m, 0, 1000);
  c.post_size_m = r.DoubleIn("size_m", c.post_size_m, 0.01, 5);
  c.post_height_m = r.DoubleIn("height_m", c.post_height_m, 0.1, 50);
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
  g->CheckKeys({"ridges", "headland_m", "side_margin_m", "wall_height_m", "posts"});
  world::GreenhouseConfig c;
  const std::optional<YamlReader> ridges = g->OptionalChild("ridges");
  const std::optional<YamlReader> posts = g->OptionalChild("posts");
  if (ridges) ReadRidges(*ridges, c);
  if (posts) ReadPosts(*posts, c);
  c.headland_m = g->DoubleIn("headland_m", c.headland_m, 0, 1000);
  c.side_margin_m = g->DoubleIn("side_margin_m", c.side_margin_m, 0, 1000);
  c.wall_height_m = g->DoubleIn("wall_height_m", c.wall_height_m, 0.1, 50);
  if (const auto problem = world::CheckGreenhouse(c)) {
    FailAt(*problem, {&*g, ridges ? &*ridges : nullptr, posts ? &*posts : nullptr});
  }
  s.greenhouse = c;
}

}  // namespace hil::harness

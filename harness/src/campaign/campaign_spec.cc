// The campaign file reader. Format (vectors/campaigns/README.md):
//
// name: acceptance-mc
// scenarios: [../scenarios/seed000_*.yaml, ../scenarios/seed004_outages.yaml]   # globs
// short: true                        # each scenario's `short:` form
// seeds: {from: 1, to: 20}           # or {from: 1, count: 20}, or a list [1, 5, 9]
// sweep:
//   combine: cartesian               # or zip (the i-th values together)
//   fields:
//     - {field: gnss.model.horizontal_sigma_m, values: [0.5, 1.0]}
// criteria:                          # per scenario and sweep point, over the seeds
//   - {metric: horizontal_rmse_m, stat: p95, max: 0.6, scenarios: "seed000_*"}
//   - {pass_fraction: 0.9}
// run: {mode: virtual, speed: 5, estimator: "{navd} --config {run_dir}/navd.conf"}
#include "hil/harness/campaign/campaign_spec.h"

#include <fnmatch.h>
#include <glob.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxRuns = 1000000;

std::vector<std::string> Glob(const YamlReader& at, const std::string& pattern,
                              const std::string& base_dir) {
  const std::string full =
      fs::path(pattern).is_absolute() ? pattern : (fs::path(base_dir) / pattern).string();
  glob_t g{};
  const int rc = glob(full.c_str(), 0, nullptr, &g);
  std::vector<std::string> out;
  for (std::size_t i = 0; rc == 0 && i < g.gl_pathc; ++i) {
    std::error_code ec;
    if (fs::is_regular_file(g.gl_pathv[i], ec))
      out.push_back(fs::path(g.gl_pathv[i]).lexically_normal().string());
  }
  globfree(&g);
  if (out.empty()) at.Fail("'" + pattern + "' matches no scenario file (looked for " + full + ")");
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> ReadScenarios(const YamlReader& root) {
  const std::string base = fs::path(root.file()).parent_path().string();
  const YamlReader s = root.Child("scenarios");
  std::vector<YamlReader> items;
  if (s.IsScalar())
    items.push_back(s);
  else
    items = s.Elements();
  if (items.empty()) s.Fail("expected at least one scenario glob");
  std::vector<std::string> files;
  std::set<std::string> seen;
  for (const YamlReader& item : items) {
    for (const auto& f : Glob(item, item.Scalar(), base.empty() ? "." : base)) {
      if (seen.insert(f).second) files.push_back(f);
    }
  }
  return files;
}

std::vector<std::uint64_t> ReadSeeds(const YamlReader& root) {
  const YamlReader s = root.Child("seeds");
  std::vector<std::uint64_t> seeds;
  if (s.IsSequence()) {
    for (const YamlReader& e : s.Elements()) {
      const std::string v = e.Scalar();
      if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos)
        e.Fail("expected a seed (a whole number ≥ 0), got '" + v + "'");
      seeds.push_back(std::stoull(v));
    }
    if (seeds.empty()) s.Fail("expected at least one seed");
  } else {
    if (!s.IsMap()) s.Fail("expected {from: A, to: B}, {from: A, count: N} or a list of seeds");
    s.CheckKeys({"from", "to", "count"});
    const std::int64_t from = s.Int("from", 1, 0, INT64_MAX / 2);
    if (s.Has("to") == s.Has("count")) s.Fail("give one of 'to' or 'count'");
    const std::int64_t count = s.Has("count") ? s.Int("count", 1, 1, kMaxRuns)
                                              : s.Int("to", from, from, from + kMaxRuns) - from + 1;
    for (std::int64_t k = 0; k < count; ++k) seeds.push_back(static_cast<std::uint64_t>(from + k));
  }
  std::set<std::uint64_t> unique(seeds.begin(), seeds.end());
  if (unique.size() != seeds.size()) s.Fail("a seed is listed twice");
  return seeds;
}

void ReadSweep(const YamlReader& root, CampaignSpec& spec) {
  const YamlReader sw = root.Child("sweep");
  sw.CheckKeys({"combine", "fields"});
  spec.zip = sw.Choice("combine", "cartesian", {"cartesian", "zip"}) == "zip";
  std::set<std::string> fields;
  for (const YamlReader& f : sw.Child("fields").Elements()) {
    f.CheckKeys({"field", "values"});
    SweepField sf;
    sf.field = f.String("field");
    try {
      SplitFieldPath(sf.field);
    } catch (const std::invalid_argument& e) {
      f.Fail("field", e.what());
    }
    if (!fields.insert(sf.field).second) f.Fail("field", "'" + sf.field + "' is swept twice");
    for (const YamlReader& v : f.Child("values").Elements()) {
      YAML::Emitter em;
      em << YAML::Flow << v.node();
      sf.values.emplace_back(em.c_str());
    }
    if (sf.values.empty()) f.Fail("values", "expected at least one value");
    if (spec.zip && !spec.sweep.empty() && sf.values.size() != spec.sweep.front().values.size())
      f.Fail("values", "combine: zip needs as many values as the first field's (" +
                           std::to_string(spec.sweep.front().values.size()) + ")");
    spec.sweep.push_back(sf);
  }
  if (spec.sweep.empty()) sw.Fail("fields", "expected at least one swept field");
}

void ReadRunSection(const YamlReader& root, CampaignSpec& spec) {
  const YamlReader r = root.Child("run");
  r.CheckKeys({"mode", "speed", "estimator"});
  if (r.Has("mode"))
    spec.run_args.insert(
        spec.run_args.end(),
        {"--mode", r.Choice("mode", "virtual", {"virtual", "realtime", "scaled"})});
  if (r.Has("speed")) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", r.DoubleIn("speed", 1, 0.01, 1000));
    spec.run_args.insert(spec.run_args.end(), {"--speed", b});
  }
  if (r.Has("estimator"))
    spec.run_args.insert(spec.run_args.end(), {"--estimator", r.String("estimator")});
}

// One sweep point's field: errors in it name the sweep, not `--set` nor the scenario's line.
ScenarioOverride SweepOverride(const std::string& field, const std::string& value) {
  return {field, value, "campaign sweep " + field + "=" + value};
}

// Every sweep value against every scenario: a value a scenario rejects is the campaign's error.
void CheckSweepValues(const YamlReader& root, const CampaignSpec& spec) {
  if (spec.sweep.empty()) return;
  const auto fields = root.Child("sweep").Child("fields").Elements();
  for (const auto& file : spec.scenario_files) {
    try {
      LoadScenario(file, spec.short_form);
    } catch (const ScenarioError&) {
      continue;  // an invalid scenario is reported as its runs' error, as `hil suite` does
    }
    for (std::size_t f = 0; f < spec.sweep.size(); ++f) {
      const auto values = fields[f].Child("values").Elements();
      for (std::size_t v = 0; v < spec.sweep[f].values.size(); ++v) {
        try {
          LoadScenario(file, spec.short_form,
                       {SweepOverride(spec.sweep[f].field, spec.sweep[f].values[v])});
        } catch (const ScenarioError& e) {
          values[v].Fail("scenario " + file + " rejects " + spec.sweep[f].field + " = " +
                         spec.sweep[f].values[v] + ": " + e.what());
        }
      }
    }
  }
}

}  // namespace

CampaignSpec ReadCampaignFile(const std::string& path) {
  const YamlReader root = YamlReader::LoadFile(path);
  root.CheckKeys(
      {"name", "description", "scenarios", "short", "seeds", "sweep", "criteria", "run"});
  CampaignSpec spec;
  spec.file = path;
  spec.source = path;
  spec.name = root.String("name");
  if (spec.name.empty() || spec.name.find_first_of("/ \t\n") != std::string::npos)
    root.Fail("name", "expected a name without spaces or slashes (it names the campaign folder)");
  spec.description = root.String("description", "");
  spec.title = "Campaign " + spec.name;
  spec.scenario_files = ReadScenarios(root);
  spec.short_form = root.Bool("short", false);
  if (root.Has("seeds")) spec.seeds = ReadSeeds(root);
  if (root.Has("sweep")) ReadSweep(root, spec);
  if (root.Has("criteria")) {
    for (const YamlReader& c : root.Child("criteria").Elements())
      spec.criteria.push_back(ReadCampaignCriterion(c));
  }
  if (root.Has("run")) ReadRunSection(root, spec);
  const auto points = SweepPoints(spec).size();
  const auto runs =
      spec.scenario_files.size() * points * std::max<std::size_t>(1, spec.seeds.size());
  if (runs > static_cast<std::size_t>(kMaxRuns))
    root.Fail("the campaign has " + std::to_string(runs) + " runs (at most " +
              std::to_string(kMaxRuns) + ")");
  CheckSweepValues(root, spec);
  return spec;
}

std::vector<std::vector<ScenarioOverride>> SweepPoints(const CampaignSpec& spec) {
  std::vector<std::vector<ScenarioOverride>> points{{}};
  if (spec.sweep.empty()) return points;
  if (spec.zip) {
    points.assign(spec.sweep.front().values.size(), {});
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (const auto& f : spec.sweep) points[i].push_back(SweepOverride(f.field, f.values[i]));
    }
    return points;
  }
  for (const auto& f : spec.sweep) {  // cartesian: the last field varies fastest
    std::vector<std::vector<ScenarioOverride>> next;
    for (const auto& p : points) {
      for (const auto& v : f.values) {
        next.push_back(p);
        next.back().push_back(SweepOverride(f.field, v));
      }
    }
    points = std::move(next);
  }
  return points;
}

}  // namespace hil::harness

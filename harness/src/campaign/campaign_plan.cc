#include "hil/harness/campaign/campaign_plan.h"

#include <filesystem>
#include <stdexcept>

namespace hil::harness {

using nlohmann::json;

CampaignPlan PlanCampaign(const CampaignSpec& spec) {
  CampaignPlan plan;
  plan.spec = spec;
  const auto points = SweepPoints(spec);
  const int width = static_cast<int>(std::to_string(points.size() - 1).size());
  for (const auto& file : spec.scenario_files) {
    const std::string stem = std::filesystem::path(file).stem().string();
    for (std::size_t p = 0; p < points.size(); ++p) {
      CampaignGroup g{stem, file, p, points[p]};
      if (points.size() > 1) {
        std::string k = std::to_string(p);
        g.id += "__p" + std::string(static_cast<std::size_t>(width) - k.size(), '0') + k;
      }
      plan.groups.push_back(g);
    }
  }
  for (std::size_t g = 0; g < plan.groups.size(); ++g) {
    const auto own = spec.file_seeds.find(plan.groups[g].scenario_file);
    const std::vector<std::uint64_t>& seeds =
        own != spec.file_seeds.end() ? own->second : spec.seeds;
    const std::size_t n = std::max<std::size_t>(1, seeds.size());
    for (std::size_t s = 0; s < n; ++s) {
      CampaignRun r;
      r.index = plan.runs.size();
      r.group = g;
      r.id = plan.groups[g].id;
      if (!seeds.empty()) {
        r.seed = seeds[s];
        r.id += "-seed" + std::to_string(*r.seed);
      }
      plan.runs.push_back(r);
    }
  }
  return plan;
}

json PlanToJson(const CampaignPlan& plan) {
  const CampaignSpec& s = plan.spec;
  json sweep = json::array();
  for (const auto& f : s.sweep) sweep.push_back({{"field", f.field}, {"values", f.values}});
  json criteria = json::array();
  for (const auto& c : s.criteria) {
    json k{{"name", c.name},           {"kind", c.kind}, {"metric", c.metric}, {"stat", c.stat},
           {"scenarios", c.scenarios}, {"max", nullptr}, {"min", nullptr}};
    if (c.max) k["max"] = *c.max;
    if (c.min) k["min"] = *c.min;
    criteria.push_back(k);
  }
  return {{"file", s.file},
          {"name", s.name},
          {"description", s.description},
          {"title", s.title},
          {"source", s.source},
          {"scenario_files", s.scenario_files},
          {"short_form", s.short_form},
          {"seeds", s.seeds},
          {"file_seeds", s.file_seeds},
          {"combine", s.zip ? "zip" : "cartesian"},
          {"sweep", sweep},
          {"criteria", criteria},
          {"run_args", s.run_args}};
}

CampaignPlan PlanFromJson(const json& j) {
  try {
    CampaignSpec s;
    s.file = j.at("file").get<std::string>();
    s.name = j.at("name").get<std::string>();
    s.description = j.at("description").get<std::string>();
    s.title = j.at("title").get<std::string>();
    s.source = j.at("source").get<std::string>();
    s.scenario_files = j.at("scenario_files").get<std::vector<std::string>>();
    s.short_form = j.at("short_form").get<bool>();
    s.seeds = j.at("seeds").get<std::vector<std::uint64_t>>();
    if (j.contains("file_seeds"))
      s.file_seeds = j.at("file_seeds").get<std::map<std::string, std::vector<std::uint64_t>>>();
    s.zip = j.at("combine").get<std::string>() == "zip";
    for (const auto& f : j.at("sweep"))
      s.sweep.push_back(
          {f.at("field").get<std::string>(), f.at("values").get<std::vector<std::string>>()});
    for (const auto& c : j.at("criteria")) {
      CampaignCriterion k;
      k.name = c.at("name").get<std::string>();
      k.kind = c.at("kind").get<std::string>();
      k.metric = c.at("metric").get<std::string>();
      k.stat = c.at("stat").get<std::string>();
      k.scenarios = c.at("scenarios").get<std::string>();
      if (c.at("max").is_number()) k.max = c.at("max").get<double>();
      if (c.at("min").is_number()) k.min = c.at("min").get<double>();
      s.criteria.push_back(k);
    }
    s.run_args = j.at("run_args").get<std::vector<std::string>>();
    return PlanCampaign(s);
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("malformed campaign plan: ") + e.what());
  }
}

std::vector<std::size_t> ShardRuns(const CampaignPlan& plan, int shard, int shards) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    if (ShardOfRun(k, shards) == shard) out.push_back(k);
  }
  return out;
}

int ShardOfRun(std::size_t index, int shards) {
  return static_cast<int>(index % static_cast<std::size_t>(std::max(1, shards))) + 1;
}

}  // namespace hil::harness

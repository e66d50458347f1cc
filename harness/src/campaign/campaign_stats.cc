#include "hil/harness/campaign/campaign_stats.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>

namespace hil::harness {
namespace {

using nlohmann::json;

json ValueIn(const json& run, const std::string& metric) {
  if (!run.contains("metric_table") || !run["metric_table"].is_object()) return nullptr;
  const json& t = run["metric_table"];
  return t.contains(metric) ? t[metric] : json(nullptr);
}

bool Within(const CampaignCriterion& c, double v) {
  return c.max ? v <= *c.max : v >= c.min.value_or(0.0);
}

json EvaluateGroup(const CampaignCriterion& c, const json& group, const json& runs) {
  json failing = json::array();
  json value = nullptr;
  std::size_t n = 0;
  const std::string id = group.value("id", "");
  if (c.kind == "pass_fraction") {
    std::size_t passed = 0;
    for (const auto& r : runs) {
      if (r.value("group", "") != id) continue;
      ++n;
      if (r.value("pass", false))
        ++passed;
      else
        failing.push_back(r.value("id", ""));
    }
    if (n > 0) value = static_cast<double>(passed) / static_cast<double>(n);
  } else {
    const json& stats = group["metrics"].contains(c.metric) ? group["metrics"][c.metric] : json();
    value = stats.is_object() ? StatOf(stats, c.stat) : json(nullptr);
    for (const auto& r : runs) {
      if (r.value("group", "") != id) continue;
      ++n;
      const json v = ValueIn(r, c.metric);
      if (!v.is_number() || !Within(c, v.get<double>())) failing.push_back(r.value("id", ""));
    }
  }
  const bool pass = value.is_number() && Within(c, value.get<double>());
  return {{"group", id},    {"scenario", group.value("scenario", "")},
          {"value", value}, {"n", n},
          {"pass", pass},   {"failing_runs", failing}};
}

}  // namespace

double SortedQuantile(const std::vector<double>& sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

json MetricStats(const std::vector<json>& values) {
  std::vector<double> x;
  for (const auto& v : values) {
    if (v.is_number()) x.push_back(v.get<double>());
  }
  if (x.empty())
    return {{"n", 0},         {"mean", nullptr}, {"p50", nullptr},
            {"p95", nullptr}, {"min", nullptr},  {"max", nullptr}};
  std::sort(x.begin(), x.end());
  double sum = 0;
  for (double v : x) sum += v;
  return {{"n", x.size()},
          {"mean", sum / static_cast<double>(x.size())},
          {"p50", SortedQuantile(x, 0.5)},
          {"p95", SortedQuantile(x, 0.95)},
          {"min", x.front()},
          {"max", x.back()}};
}

json StatOf(const json& stats, const std::string& stat) {
  return stats.contains(stat) ? stats[stat] : json(nullptr);
}

json EvaluateCampaignCriteria(const CampaignPlan& plan, const json& groups, const json& runs) {
  json out = json::array();
  for (const CampaignCriterion& c : plan.spec.criteria) {
    json k{{"name", c.name},
           {"kind", c.kind},
           {"metric", c.metric},
           {"stat", c.kind == "pass_fraction" ? "pass_fraction" : c.stat},
           {"relation", c.max ? "max" : "min"},
           {"threshold", c.max ? *c.max : c.min.value_or(0.0)},
           {"scenarios", c.scenarios},
           {"groups", json::array()}};
    bool pass = true;
    for (const auto& g : groups) {
      const std::string scenario = g.value("scenario", "");
      if (!c.scenarios.empty() && fnmatch(c.scenarios.c_str(), scenario.c_str(), 0) != 0) continue;
      json e = EvaluateGroup(c, g, runs);
      pass = pass && e.value("pass", false);
      k["groups"].push_back(e);
    }
    if (k["groups"].empty()) pass = false;  // a criterion that judges nothing does not pass
    k["pass"] = pass;
    out.push_back(k);
  }
  return out;
}

}  // namespace hil::harness

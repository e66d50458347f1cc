#include "hil/harness/campaign/campaign_summary.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "hil/harness/campaign/campaign_stats.h"
#include "hil/harness/campaign/suite_report.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string SettingsLabel(const CampaignGroup& g) {
  std::string s;
  for (const auto& o : g.settings) s += (s.empty() ? "" : ", ") + o.field + " = " + o.value;
  return s;
}

SuiteScenarioInfo LoadInfo(const CampaignFolder& f, const CampaignGroup& g) {
  SuiteScenarioInfo info;
  info.file = g.scenario_file;
  fs::path p(g.scenario_file);
  if (p.is_relative() && !f.workdir.empty()) p = fs::path(f.workdir) / p;
  try {
    info.scenario = LoadScenario(p.string(), f.plan.spec.short_form, g.settings);
  } catch (const ScenarioError& e) {
    info.error = e.what();
  }
  return info;
}

// A group's statistics over its runs of every key of `table` (metric_table: the estimate's
// figures; baseline_table: the raw GNSS fixes' figures) with a number in some run.
json GroupMetrics(const std::vector<json>& mine, const char* table) {
  std::set<std::string> keys;
  for (const auto& r : mine) {
    if (!r.contains(table)) continue;
    for (const auto& [k, v] : r[table].items()) {
      if (v.is_number()) keys.insert(k);
    }
  }
  json metrics = json::object();
  for (const auto& k : keys) {
    std::vector<json> values;
    for (const auto& r : mine)
      values.push_back(r.contains(table) ? r[table].value(k, json(nullptr)) : json(nullptr));
    metrics[k] = MetricStats(values);
  }
  return metrics;
}

// One group's entries: the suite's side-by-side one and the campaign's statistics.
void SummariseGroup(const CampaignFolder& f, std::size_t gi, const json& runs, json& summary) {
  const CampaignGroup& g = f.plan.groups[gi];
  const SuiteScenarioInfo info = LoadInfo(f, g);
  json mine_json = json::array();
  std::vector<json> mine;
  for (const auto& r : runs) {
    if (r.value("group", "") == g.id) {
      mine.push_back(r);
      mine_json.push_back(r);
    }
  }
  json s = SummariseScenarios({info}, mine_json).at(0);
  const std::string label = SettingsLabel(g);
  if (!label.empty()) s["scenario"] = s["scenario"].get<std::string>() + " [" + label + "]";
  s["group"] = g.id;
  summary["scenarios"].push_back(s);
  json criteria_metrics = json::array();
  if (info.scenario) {
    for (const auto& c : info.scenario->criteria) criteria_metrics.push_back(c.metric);
  }
  json settings = json::array();
  for (const auto& o : g.settings) settings.push_back({{"field", o.field}, {"value", o.value}});
  std::size_t passed = 0;
  for (const auto& r : mine) passed += r.value("pass", false) ? 1 : 0;
  summary["groups"].push_back(
      {{"id", g.id},
       {"scenario_file", g.scenario_file},
       {"scenario",
        info.scenario ? info.scenario->name : fs::path(g.scenario_file).stem().string()},
       {"settings", settings},
       {"runs", mine.size()},
       {"passed", passed},
       {"criteria_metrics", criteria_metrics},
       {"metrics", GroupMetrics(mine, "metric_table")},
       {"baselines", GroupMetrics(mine, "baseline_table")}});
}

}  // namespace

json SummariseCampaign(const CampaignFolder& f, const json& runs,
                       const std::vector<std::string>& missing) {
  const CampaignSpec& spec = f.plan.spec;
  json summary{{"title", spec.title},
               {"campaign", spec.name},
               {"description", spec.description},
               {"scenario_dir", spec.source},
               {"short_form", spec.short_form},
               {"seeds", std::max<std::size_t>(1, spec.seeds.size())},
               {"runs_planned", f.plan.runs.size()},
               {"complete", missing.empty()},
               {"missing_runs", missing},
               {"runs", runs},
               {"scenarios", json::array()},
               {"groups", json::array()}};
  std::size_t passed = 0, failed = 0, invalid = 0;
  for (const auto& r : runs) {
    const int code = r.value("exit_code", -1);
    code == 0 ? ++passed : code == 1 ? ++failed : ++invalid;
  }
  summary["passed"] = passed;
  summary["failed"] = failed;
  summary["invalid"] = invalid;
  for (std::size_t g = 0; g < f.plan.groups.size(); ++g) SummariseGroup(f, g, runs, summary);
  summary["criteria"] = EvaluateCampaignCriteria(f.plan, summary["groups"], runs);
  bool criteria_pass = true;
  for (const auto& c : summary["criteria"]) criteria_pass = criteria_pass && c.value("pass", false);
  // with criteria across runs, they judge the campaign (a Monte Carlo run may fail alone);
  // without, and in `hil suite` (no campaign file; its criteria across runs are its scenarios'
  // `statistical:` claims beside their per-run bounds), every run must pass
  const bool runs_pass = spec.criteria.empty() || spec.file.empty() ? failed == 0 : true;
  summary["pass"] = missing.empty() && invalid == 0 && !runs.empty() && runs_pass && criteria_pass;
  summary["report_metrics"] = ReportMetrics(summary);
  return summary;
}

std::vector<std::string> ReportMetrics(const json& summary) {
  std::vector<std::string> out{"horizontal_rmse_m", "cep95_m", "max_horizontal_error_m"};
  const auto add = [&](const std::string& m) {
    if (!m.empty() && std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  };
  for (const auto& g : summary.value("groups", json::array())) {
    for (const auto& m : g.value("criteria_metrics", json::array())) add(m.get<std::string>());
  }
  for (const auto& c : summary.value("criteria", json::array())) add(c.value("metric", ""));
  return out;
}

}  // namespace hil::harness

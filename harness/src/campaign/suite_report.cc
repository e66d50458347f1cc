#include "hil/harness/campaign/suite_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "hil/harness/report/markdown.h"

namespace hil::harness {
namespace {

using nlohmann::json;

// A metric's value in a readable unit: lengths in cm (the papers' unit; m from 10 m, km from 1 km),
// others as they are.
std::string Fmt(const std::string& metric, const json& v) {
  if (!v.is_number()) return "n/a";
  const double x = v.get<double>();
  char b[48];
  const auto ends = [&](const char* s) {
    const std::string suf(s);
    return metric.size() >= suf.size() &&
           metric.compare(metric.size() - suf.size(), suf.size(), suf) == 0;
  };
  if (ends("_m") && std::abs(x) >= 1000.0)
    std::snprintf(b, sizeof b, "%.1f km", x / 1000.0);
  else if (ends("_m") && std::abs(x) >= 10.0)
    std::snprintf(b, sizeof b, "%.1f m", x);
  else if (ends("_m"))
    std::snprintf(b, sizeof b, "%.1f cm", x * 100.0);
  else if (ends("_deg"))
    std::snprintf(b, sizeof b, "%.2f°", x);
  else if (ends("_s"))
    std::snprintf(b, sizeof b, "%.1f s", x);
  else
    std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

// "mean ± std (min–max, n)" of a SpreadOf object.
std::string FmtSpread(const std::string& metric, const json& s) {
  if (!s.is_object() || s.value("n", 0) == 0) return "n/a";
  const int n = s.value("n", 0);
  if (n == 1) return Fmt(metric, s["mean"]);
  return Fmt(metric, s["mean"]) + " ± " + Fmt(metric, s["std"]) + " (" + Fmt(metric, s["min"]) +
         " – " + Fmt(metric, s["max"]) + ", " + std::to_string(n) + " seeds)";
}

json Lookup(const json& run, const char* table, const std::string& key) {
  if (!run.contains(table) || !run[table].is_object() || !run[table].contains(key)) return nullptr;
  return run[table][key];
}

// A scenario's reference figures: each paper's figure beside our runs' and the raw GNSS baseline.
json PaperJson(const SuiteScenarioInfo& info, const std::vector<json>& mine) {
  json paper = json::array();
  if (info.scenario) {
    for (const PaperFigure& p : info.scenario->paper) {
      std::vector<json> ours, base;
      for (const auto& r : mine) {
        ours.push_back(Lookup(r, "metric_table", p.metric));
        base.push_back(Lookup(r, "baseline_table", p.metric));
      }
      json f{{"source", p.source},        {"metric", p.metric}, {"relation", p.relation},
             {"finding", p.finding},      {"note", p.note},     {"ours", SpreadOf(ours)},
             {"raw_gnss", SpreadOf(base)}};
      f["value"] = p.value ? json(*p.value) : json(nullptr);
      paper.push_back(f);
    }
  }
  return paper;
}

// A scenario's criteria, by position in its list: pass when every seed passed.
json CriteriaJson(const SuiteScenarioInfo& info, const std::vector<json>& mine) {
  json criteria = json::array();
  std::size_t n_criteria = 0;
  for (const auto& r : mine)
    n_criteria = std::max(n_criteria, r.value("criteria", json::array()).size());
  for (std::size_t k = 0; k < n_criteria; ++k) {
    std::vector<json> values, thresholds;
    std::size_t ok = 0, seen = 0;
    std::string name;
    for (const auto& r : mine) {
      const json crit = r.value("criteria", json::array());
      if (k >= crit.size()) continue;
      ++seen;
      name = crit[k].value("name", "criterion");
      values.push_back(crit[k].value("value", json(nullptr)));
      thresholds.push_back(crit[k].value("threshold", json(nullptr)));
      ok += crit[k].value("pass", false) ? 1 : 0;
    }
    const std::string metric = info.scenario && k < info.scenario->criteria.size()
                                   ? info.scenario->criteria[k].metric
                                   : "";
    criteria.push_back({{"name", name},
                        {"metric", metric},
                        {"passed", ok},
                        {"runs", mine.size()},
                        {"pass", seen == mine.size() && ok == mine.size()},
                        {"value", SpreadOf(values)},
                        {"threshold", SpreadOf(thresholds)}});
  }
  return criteria;
}

// A scenario's outages, by position: the spread over the seeds of the per-axis maxima (paper 004).
json OutagesJson(const std::vector<json>& mine) {
  json outages = json::array();
  std::size_t n_outages = 0;
  for (const auto& r : mine) {
    if (r.contains("outages") && r["outages"].is_array())
      n_outages = std::max(n_outages, r["outages"].size());
  }
  for (std::size_t k = 0; k < n_outages; ++k) {
    std::map<std::string, std::vector<json>> v;
    json o;
    for (const auto& r : mine) {
      if (!r.contains("outages") || k >= r["outages"].size()) continue;
      const json& x = r["outages"][k];
      o["start_s"] = x.value("start_s", 0.0);
      o["end_s"] = x.value("end_s", 0.0);
      for (const char* key : {"max_east_error_m", "max_north_error_m", "max_up_error_m",
                              "max_horizontal_error_m", "reconvergence_time_s"}) {
        v[key].push_back(x.value(key, json(nullptr)));
      }
    }
    for (auto& [key, vals] : v) o[key] = SpreadOf(vals);
    outages.push_back(o);
  }
  return outages;
}

// The reference figures table: the papers' figures beside ours and the raw GNSS.
void AppendPaperMd(std::string& md, const json& scenarios) {
  md +=
      "## Reference figures\n\n| scenario | source | metric | paper | ours | raw GNSS (one "
      "receiver) | note |\n"
      "|---|---|---|---|---|---|---|\n";
  bool any_paper = false;
  for (const auto& s : scenarios) {
    for (const auto& p : s.value("paper", json::array())) {
      any_paper = true;
      const std::string metric = p.value("metric", "");
      std::string paper = p["value"].is_number() ? Fmt(metric, p["value"]) : "";
      const std::string rel = p.value("relation", "about");
      if (!paper.empty() && rel == "below") paper = "< " + paper;
      if (!paper.empty() && rel == "above") paper = "> " + paper;
      const std::string finding = p.value("finding", "");
      if (!finding.empty()) paper += (paper.empty() ? "" : " — ") + finding;
      md += "| " + MarkdownCell(s.value("scenario", "")) + " | " +
            MarkdownCell(p.value("source", "")) + " | `" + metric + "` | " + MarkdownCell(paper) +
            " | " + FmtSpread(metric, p["ours"]) + " | " + FmtSpread(metric, p["raw_gnss"]) +
            " | " + MarkdownCell(p.value("note", "")) + " |\n";
    }
  }
  if (!any_paper) md += "| (no scenario has a `paper:` section) | | | | | | |\n";
}

// The outages table, when a scenario has outages.
void AppendOutagesMd(std::string& md, const json& scenarios) {
  char line[512];
  bool any_outage = false;
  for (const auto& s : scenarios)
    any_outage = any_outage || !s.value("outages", json::array()).empty();
  if (any_outage) {
    md +=
        "\n## GNSS outages: maximum error inside each outage (paper 004: < 11 cm in E, N and U)\n\n"
        "| scenario | outage | max east | max north | max up | max horizontal | re-converged after "
        "|\n"
        "|---|---|---|---|---|---|---|\n";
    for (const auto& s : scenarios) {
      for (const auto& o : s.value("outages", json::array())) {
        std::snprintf(line, sizeof line, "%.0f–%.0f s", o.value("start_s", 0.0),
                      o.value("end_s", 0.0));
        md += "| " + MarkdownCell(s.value("scenario", "")) + " | " + line + " | " +
              FmtSpread("e_m", o["max_east_error_m"]) + " | " +
              FmtSpread("e_m", o["max_north_error_m"]) + " | " +
              FmtSpread("e_m", o["max_up_error_m"]) + " | " +
              FmtSpread("e_m", o["max_horizontal_error_m"]) + " | " +
              FmtSpread("t_s", o["reconvergence_time_s"]) + " |\n";
      }
    }
  }
}

// The criteria table: every criterion of every scenario with the seeds it passed in.
void AppendCriteriaMd(std::string& md, const json& scenarios) {
  char line[512];
  md +=
      "\n## Criteria\n\n| scenario | criterion | value | threshold | seeds passed | result "
      "|\n|---|---|---|---|---|---|\n";
  for (const auto& s : scenarios) {
    const std::string name = MarkdownCell(s.value("scenario", ""));
    if (s.contains("error")) {
      md += "| " + name + " | invalid scenario | " + MarkdownCell(s.value("error", "")) +
            " | | | **INVALID** |\n";
      continue;
    }
    const json crit = s.value("criteria", json::array());
    if (crit.empty())
      md += "| " + name + " | (no criteria) | | | | " +
            (s.value("pass", false) ? "PASS" : "**FAIL**") + " |\n";
    for (const auto& c : crit) {
      const std::string cname = c.value("name", "");
      const std::string metric = c.value("metric", "");
      std::snprintf(line, sizeof line, "%d/%d", c.value("passed", 0), c.value("runs", 0));
      md += "| " + name + " | " + MarkdownCell(cname) + " | " + FmtSpread(metric, c["value"]) +
            " | " + FmtSpread(metric, c["threshold"]) + " | " + line + " | " +
            (c.value("pass", false) ? "PASS" : "**FAIL**") + " |\n";
    }
    for (const auto& p : s.value("problems", json::array())) {
      md += "| " + name + " | run problem | " +
            MarkdownCell(p.is_string() ? p.get<std::string>() : p.dump()) + " | | | **FAIL** |\n";
    }
  }
}

}  // namespace

json SpreadOf(const std::vector<json>& values) {
  std::vector<double> x;
  for (const auto& v : values) {
    if (v.is_number()) x.push_back(v.get<double>());
  }
  if (x.empty())
    return {{"n", 0}, {"mean", nullptr}, {"std", nullptr}, {"min", nullptr}, {"max", nullptr}};
  double mean = 0;
  for (double v : x) mean += v / static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const double sd = x.size() > 1 ? std::sqrt(ss / static_cast<double>(x.size() - 1)) : 0.0;
  return {{"n", x.size()},
          {"mean", mean},
          {"std", sd},
          {"min", *std::min_element(x.begin(), x.end())},
          {"max", *std::max_element(x.begin(), x.end())}};
}

json SummariseScenarios(const std::vector<SuiteScenarioInfo>& scenarios, const json& runs) {
  json out = json::array();
  for (const SuiteScenarioInfo& info : scenarios) {
    std::vector<json> mine;
    for (const auto& r : runs) {
      if (r.value("scenario_file", "") == info.file) mine.push_back(r);
    }
    json s;
    s["scenario_file"] = info.file;
    s["scenario"] =
        info.scenario ? info.scenario->name : std::filesystem::path(info.file).stem().string();
    s["description"] = info.scenario ? info.scenario->description : "";
    s["short_form"] = info.scenario && info.scenario->short_form;
    if (!info.error.empty()) s["error"] = info.error;
    s["runs"] = mine.size();
    std::size_t passed = 0;
    json seeds = json::array(), errors = json::array();
    for (const auto& r : mine) {
      passed += r.value("pass", false) ? 1 : 0;
      seeds.push_back(r.value("seed", json(nullptr)));
      if (r.contains("error")) errors.push_back(r["error"]);
      for (const auto& p : r.value("problems", json::array())) errors.push_back(p);
    }
    s["passed"] = passed;
    s["seeds"] = seeds;
    s["problems"] = errors;
    s["pass"] = !mine.empty() && passed == mine.size() && info.error.empty();
    // reference figures: the run's metric beside the paper's, and the raw GNSS baseline
    s["paper"] = PaperJson(info, mine);
    // criteria, by position in the scenario's list: pass when every seed passed
    s["criteria"] = CriteriaJson(info, mine);
    // outages, by position: the per-axis maxima of paper 004
    s["outages"] = OutagesJson(mine);
    out.push_back(s);
  }
  return out;
}

std::string SuiteMarkdown(const json& summary) {
  std::string md;
  char line[512];
  const json scenarios = summary.value("scenarios", json::array());
  md += "# " +
        summary.value("title", std::string("Acceptance suite: our figures beside the papers'")) +
        "\n\n";
  // no wall times here: the report is the same bytes whoever ran the runs (timing.json has them)
  std::snprintf(line, sizeof line, "Scenarios from `%s`, %s form, %d seed(s) per scenario. ",
                summary.value("scenario_dir", "").c_str(),
                summary.value("short_form", false) ? "**short**" : "full",
                summary.value("seeds", 1));
  md += line;
  std::snprintf(line, sizeof line, "Runs: %d passed, %d failed, %d invalid — **%s**.\n\n",
                summary.value("passed", 0), summary.value("failed", 0), summary.value("invalid", 0),
                summary.value("pass", false) ? "PASS" : "FAIL");
  md += line;
  md +=
      "Values are the mean ± sample standard deviation over the seeds (min – max). A criterion "
      "passes when it "
      "passes in every seed. Reference figures come from each scenario file's `paper:` "
      "section.\n\n";

  AppendPaperMd(md, scenarios);

  AppendOutagesMd(md, scenarios);

  AppendCriteriaMd(md, scenarios);

  md += "\n## Runs\n\n| run | seed | result |\n|---|---|---|\n";
  for (const auto& r : summary.value("runs", json::array())) {
    const int code = r.value("exit_code", -1);
    md += "| " + MarkdownCell(std::filesystem::path(r.value("run_dir", "")).filename().string()) +
          " | " +
          (r.contains("seed") && r.at("seed").is_number()
               ? std::to_string(r.at("seed").get<std::uint64_t>())
               : std::string("-")) +
          " | " +
          (code == 0   ? "PASS"
           : code == 1 ? "FAIL"
                       : "ERROR (" + std::to_string(code) + ")") +
          " |\n";
  }
  return md;
}

}  // namespace hil::harness

#include "hil/harness/campaign/campaign_report.h"

#include <cstdio>
#include <set>

#include "hil/harness/campaign/campaign_stats.h"
#include "hil/harness/campaign/suite_report.h"
#include "hil/harness/core/build_info.h"
#include "hil/harness/report/markdown.h"
#include "hil/harness/report/report.h"

namespace hil::harness {
namespace {

using nlohmann::json;

std::string Num(const json& v) {
  if (!v.is_number()) return "n/a";
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v.get<double>());
  return b;
}

std::string Joined(const json& ids, std::size_t most) {
  std::string s;
  std::size_t k = 0;
  for (const auto& id : ids) {
    if (k++ == most) return s + ", … (" + std::to_string(ids.size()) + " in all)";
    s += (s.empty() ? "" : ", ") + id.get<std::string>();
  }
  return s.empty() ? "none" : s;
}

// Rows (scenario, criterion, value, threshold, result, failing runs) of the campaign criteria.
std::vector<std::vector<std::string>> CriteriaRows(const json& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : summary.value("criteria", json::array())) {
    const std::string rel = c.value("relation", "max") == "max" ? "≤ " : "≥ ";
    if (c["groups"].empty())
      rows.push_back({"(no group matches '" + c.value("scenarios", "") + "')", c.value("name", ""),
                      "n/a", rel + Num(c["threshold"]), "FAIL", ""});
    for (const auto& g : c["groups"]) {
      rows.push_back({g.value("group", ""), c.value("name", ""),
                      Num(g["value"]) + " (" + std::to_string(g.value("n", 0)) + " runs)",
                      rel + Num(c["threshold"]), g.value("pass", false) ? "PASS" : "FAIL",
                      Joined(g["failing_runs"], 12)});
    }
  }
  return rows;
}

// Rows (group, metric, n, mean, p50, p95, max, then the raw GNSS fixes' mean and p95 of the same
// figure where the runs have one, and the mean's ratio fused/raw) of the report metrics.
std::vector<std::vector<std::string>> MetricRows(const json& summary) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& g : summary.value("groups", json::array())) {
    const json raw_all = g.value("baselines", json::object());
    for (const auto& m : summary.value("report_metrics", json::array())) {
      const std::string metric = m.get<std::string>();
      if (!g["metrics"].contains(metric)) continue;
      const json& st = g["metrics"][metric];
      const json raw = raw_all.value(metric, json::object());
      const json raw_mean = raw.value("mean", json(nullptr));
      json ratio(nullptr);
      if (raw_mean.is_number() && st["mean"].is_number() && raw_mean.get<double>() > 0)
        ratio = st["mean"].get<double>() / raw_mean.get<double>();
      rows.push_back({g.value("id", ""), metric, std::to_string(st.value("n", 0)), Num(st["mean"]),
                      Num(st["p50"]), Num(st["p95"]), Num(st["max"]), Num(raw_mean),
                      Num(raw.value("p95", json(nullptr))), Num(ratio)});
    }
  }
  return rows;
}

// The run's result word and the criteria it failed (or its error).
std::pair<std::string, std::string> RunResult(const json& r) {
  const int code = r.value("exit_code", -1);
  std::string failed;
  for (const auto& c : r.value("criteria", json::array())) {
    if (!c.value("pass", false)) failed += (failed.empty() ? "" : "; ") + c.value("name", "");
  }
  return {code == 0   ? "PASS"
          : code == 1 ? "FAIL"
                      : "ERROR " + std::to_string(code),
          failed.empty() ? r.value("error", "") : failed};
}

// The run's own report, relative to the campaign folder (every campaign run writes one).
std::string RunReportLink(const json& r) { return r.value("run_dir", "") + "/report.html"; }

std::string MdTable(const std::vector<std::string>& head,
                    const std::vector<std::vector<std::string>>& rows) {
  std::string s = "|", sep = "|";
  for (const auto& h : head) s += " " + h + " |", sep += "---|";
  s += "\n" + sep + "\n";
  for (const auto& r : rows) {
    s += "|";
    for (const auto& c : r) s += " " + MarkdownCell(c) + " |";
    s += "\n";
  }
  return s;
}

std::string HtmlTable(const std::vector<std::string>& head,
                      const std::vector<std::vector<std::string>>& rows) {
  std::string s = "<table>\n<tr>";
  for (const auto& h : head) s += "<th>" + XmlEscape(h) + "</th>";
  s += "</tr>\n";
  for (const auto& r : rows) {
    s += "<tr>";
    for (const auto& c : r) {
      const bool fail = c == "FAIL" || c.rfind("ERROR", 0) == 0;
      s += std::string(fail ? "<td class=\"fail\">" : "<td>") + XmlEscape(c) + "</td>";
    }
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

const std::vector<std::string> kCriteriaHead{"group", "criterion", "value",
                                             "bound", "result",    "runs that break it"};
const std::vector<std::string> kMetricHead{"group",        "metric",        "n",   "mean",
                                           "p50",          "p95",           "max", "raw GNSS mean",
                                           "raw GNSS p95", "mean fused/raw"};

std::string Verdict(const json& summary) {
  char b[256];
  std::snprintf(
      b, sizeof b, "%zu of %zu planned runs recorded%s: %d passed, %d failed, %d invalid.",
      summary.value("runs", json::array()).size(), summary.value("runs_planned", 0UL),
      summary.value("complete", false) ? "" : " (**partial merge**)", summary.value("passed", 0),
      summary.value("failed", 0), summary.value("invalid", 0));
  return b;
}

// What was run: the campaign file, its scenarios, seeds and form, and the hil that merged it
// (nothing of the machine or the time: a merge is the same bytes wherever and whenever it runs).
std::string WhatWasRunHtml(const json& summary) {
  std::set<std::string> files;
  for (const auto& g : summary.value("groups", json::array()))
    files.insert(g.value("scenario_file", ""));
  const auto row = [](const std::string& key, const std::string& value) {
    return "<tr><th>" + key + "</th><td>" + XmlEscape(value) + "</td></tr>";
  };
  std::string h = "<h2>What was run</h2>\n<table class=\"kv\">";
  h += row("campaign", summary.value("campaign", ""));
  h += row("campaign file", summary.value("scenario_dir", ""));
  h += row("scenario files", std::to_string(files.size()));
  h += row("groups (scenario x sweep point)",
           std::to_string(summary.value("groups", json::array()).size()));
  h += row("seeds per group", std::to_string(summary.value("seeds", 0)));
  h += row("form", summary.value("short_form", false) ? "short (each scenario's short: form)"
                                                      : "full length");
  h += row("runs planned", std::to_string(summary.value("runs_planned", 0)));
  h += row("merged by", "hil " + std::string(HilVersion()) + ", commit " +
                            std::string(HilCommit()) + " (each run's report.html names its own)");
  return h + "</table>\n";
}

// The groups: each one's scenario file and sweep point, and how many of its runs passed (the
// group ids' "__p0", "__p1" say nothing by themselves).
std::string GroupsHtml(const json& summary) {
  std::string h =
      "<h2>Groups</h2>\n<table>\n<tr><th>group</th><th>scenario file</th>"
      "<th>sweep point</th><th>runs</th><th>passed</th></tr>\n";
  for (const auto& g : summary.value("groups", json::array())) {
    const int runs = g.value("runs", 0), passed = g.value("passed", 0);
    const std::string settings = GroupSettingsText(g);
    h += "<tr><td>" + XmlEscape(g.value("id", "")) + "</td><td>" +
         XmlEscape(g.value("scenario_file", "")) + "</td><td>" +
         (settings.empty() ? "the scenario as written" : XmlEscape(settings)) + "</td><td>" +
         std::to_string(runs) + "</td><td" + (passed < runs ? " class=\"fail\"" : "") + ">" +
         std::to_string(passed) + "</td></tr>\n";
  }
  return h + "</table>\n";
}

}  // namespace

std::string GroupSettingsText(const json& group) {
  std::string s;
  for (const auto& f : group.value("settings", json::array())) {
    const json& v = f.value("value", json(nullptr));
    s += (s.empty() ? "" : ", ") + f.value("field", "") + " = " +
         (v.is_string() ? v.get<std::string>() : v.dump());
  }
  return s;
}

std::string CampaignMarkdown(const json& summary) {
  std::string md = SuiteMarkdown(summary);
  md += "\n## Campaign\n\n" + Verdict(summary) + " Campaign verdict: **" +
        (summary.value("pass", false) ? "PASS" : "FAIL") + "**";
  if (!summary.value("complete", false))
    md += "; runs missing: " + Joined(summary["missing_runs"], 20);
  md += ".\n";
  if (!summary.value("criteria", json::array()).empty()) {
    md += "\n### Criteria across runs (per scenario and sweep point, over the seeds)\n\n" +
          MdTable(kCriteriaHead, CriteriaRows(summary));
  }
  md +=
      "\n### Metrics over the seeds (p50, p95: linear interpolation between order statistics)\n\n" +
      MdTable(kMetricHead, MetricRows(summary));
  md +=
      "\nRaw GNSS: the same figure of the receiver's own fixes in the same runs (report.json "
      "`baseline_table`); fused/raw below 1 means the estimate beats the receiver.\n";
  md += "\n### CDF plots across seeds\n\n";
  for (const auto& m : summary.value("report_metrics", json::array())) {
    if (!CdfSvg(summary, m.get<std::string>()).empty())
      md += "- [" + m.get<std::string>() + "](plots/cdf_" + m.get<std::string>() + ".svg)\n";
  }
  md += "\n### Runs\n\n| run | group | result | failed criteria |\n|---|---|---|---|\n";
  for (const auto& r : summary.value("runs", json::array())) {
    const auto [result, failed] = RunResult(r);
    md += "| [" + MarkdownCell(r.value("id", "")) + "](" + RunReportLink(r) + ") | " +
          MarkdownCell(r.value("group", "")) + " | " + result + " | " + MarkdownCell(failed) +
          " |\n";
  }
  return md;
}

std::string CampaignHtml(const json& summary) {
  std::string h =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" +
      XmlEscape(summary.value("title", "")) +
      "</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;"
      "margin-bottom:1em}td,th{border:1px solid #aaa;padding:2px 6px;font-size:13px}"
      "td.fail{background:#fdd}table.kv "
      "th{text-align:left;background:#f4f4f4}.pass{color:#176317}.fail{color:#b00020}</style></"
      "head><body>\n";
  const bool pass = summary.value("pass", false);
  h += "<h1>" + XmlEscape(summary.value("title", "")) + " <span class=\"" +
       (pass ? "pass\">PASS" : "fail\">FAIL") + "</span></h1>\n<p>" + XmlEscape(Verdict(summary)) +
       " Campaign verdict: <b>" + (pass ? "PASS" : "FAIL") + "</b></p>\n";
  h += WhatWasRunHtml(summary) + GroupsHtml(summary);
  if (!summary.value("complete", false))
    h += "<p class=\"fail\">Runs missing: " + XmlEscape(Joined(summary["missing_runs"], 50)) +
         "</p>\n";
  if (!summary.value("criteria", json::array()).empty())
    h += "<h2>Criteria across runs</h2>\n" + HtmlTable(kCriteriaHead, CriteriaRows(summary));
  h += "<h2>Metrics over the seeds</h2>\n" + HtmlTable(kMetricHead, MetricRows(summary)) +
       "<p>Raw GNSS: the same figure of the receiver's own fixes in the same runs (report.json "
       "<code>baseline_table</code>); fused/raw below 1 means the estimate beats the "
       "receiver.</p>\n";
  h += "<h2>CDF plots across seeds</h2>\n";
  for (const auto& m : summary.value("report_metrics", json::array())) h += CdfSvg(summary, m);
  h += "<h2>Runs</h2>\n<table>\n<tr><th>run (its report)</th><th>group</th><th>result</th>"
       "<th>failed criteria</th></tr>\n";
  for (const auto& r : summary.value("runs", json::array())) {
    const auto [result, failed] = RunResult(r);
    h += "<tr><td><a href=\"" + XmlEscape(RunReportLink(r)) + "\">" + XmlEscape(r.value("id", "")) +
         "</a></td><td>" + XmlEscape(r.value("group", "")) + "</td><td" +
         (result == "PASS" ? "" : " class=\"fail\"") + ">" + XmlEscape(result) + "</td><td>" +
         XmlEscape(failed) + "</td></tr>\n";
  }
  h += "</table>\n";
  return h + "</body></html>\n";
}

std::string CampaignJunit(const json& summary) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" +
                    XmlEscape(summary.value("title", "hil campaign")) + "\">\n";
  const auto suite = [&](const std::string& name,
                         const std::vector<std::pair<std::string, std::string>>& cases) {
    std::size_t failures = 0;
    for (const auto& t : cases) failures += t.second.empty() ? 0 : 1;
    out += "  <testsuite name=\"" + XmlEscape(name) + "\" tests=\"" + std::to_string(cases.size()) +
           "\" failures=\"" + std::to_string(failures) + "\">\n";
    for (const auto& [tname, msg] : cases) {
      out +=
          "    <testcase classname=\"" + XmlEscape(name) + "\" name=\"" + XmlEscape(tname) + "\">";
      if (!msg.empty()) out += "<failure message=\"" + XmlEscape(msg) + "\"/>";
      out += "</testcase>\n";
    }
    out += "  </testsuite>\n";
  };
  for (const auto& r : summary.value("runs", json::array())) {
    std::vector<std::pair<std::string, std::string>> cases;
    if (r.contains("metric_table")) {
      for (const auto& k : r.value("criteria", json::array())) {
        std::string msg;
        if (!k.value("pass", false))
          msg = "value " + Num(k.value("value", json(nullptr))) + " against threshold " +
                Num(k.value("threshold", json(nullptr)));
        cases.emplace_back(k.value("name", "criterion"), msg);
      }
      for (const auto& p : r.value("problems", json::array()))
        cases.emplace_back("run", p.get<std::string>());
    } else {
      cases.emplace_back("run", "hil run exited with " + std::to_string(r.value("exit_code", -1)) +
                                    ": " + r.value("error", ""));
    }
    suite(r.value("id", ""), cases);
  }
  if (!summary.value("criteria", json::array()).empty()) {
    std::vector<std::pair<std::string, std::string>> cases;
    for (const auto& row : CriteriaRows(summary))
      cases.emplace_back(row[0] + ": " + row[1], row[4] == "PASS"
                                                     ? ""
                                                     : "value " + row[2] + ", bound " + row[3] +
                                                           "; runs that break it: " + row[5]);
    suite("campaign criteria", cases);
  }
  return out + "</testsuites>\n";
}

}  // namespace hil::harness

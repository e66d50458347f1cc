#pragma once
/// @file
/// What `hil campaign merge` (and `hil suite`) write from a summary (campaign_summary.h): report.md
/// (the suite's side-by-side report, then the campaign's criteria, the mean, p50, p95 and max of
/// each report metric per group beside the raw GNSS fixes' mean and p95 of the same figure, links
/// to the plots, and every run linked to its own report.html), report.html (the same with the plots
/// inline), junit.xml (a testsuite per run with a testcase per scenario criterion, and one for the
/// campaign's criteria with a testcase per criterion and group) and one SVG per report metric: the
/// empirical CDF across seeds of each group. All of them the same bytes for the same summary.

#include <string>

#include <nlohmann/json.hpp>

namespace hil::harness {

std::string CampaignMarkdown(const nlohmann::json& summary);
std::string CampaignHtml(const nlohmann::json& summary);
std::string CampaignJunit(const nlohmann::json& summary);
/// What sets a group apart from the other groups of its scenario: its sweep point's field values,
/// "field = value, …" ("" without a sweep).
std::string GroupSettingsText(const nlohmann::json& group);
/// The CDF plot of `metric` (one step line per group with values; a log axis when the groups'
/// medians differ ten times or more); "" when no run has a value.
std::string CdfSvg(const nlohmann::json& summary, const std::string& metric);

}  // namespace hil::harness

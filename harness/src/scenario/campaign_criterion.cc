// The criterion reader shared by campaign files and scenarios' `statistical:` sections.
#include "hil/harness/scenario/campaign_criterion.h"

#include <algorithm>
#include <cstdio>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/scenario_keys.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace campaign_keys {  // named: the unity build joins the readers' files

using enum KeyType;

inline constexpr std::string_view kStats[] = {"mean", "p50", "p95", "max", "min"};

inline constexpr ScenarioKey kCampaignCriterion[] = {
    {"name", kString, "", "\"STAT of METRIC <= MAX\"", 0, 0, "the criterion's name in the reports"},
    {"metric", kString, "", "required (but with pass_fraction)", 0, 0,
     "a criterion metric (criteria[].metric's) or navd.<counter>"},
    {"stat", kChoice, "", "p95", 0, 0, "the statistic of the metric over the runs", kStats},
    {"max", kNumber, "", "one of max, min", -1e12, 1e12, "passes when the statistic ≤ max"},
    {"min", kNumber, "", "one of max, min", -1e12, 1e12, "passes when the statistic ≥ min"},
    {"pass_fraction", kNumber, "", "none", 0, 1,
     "instead of metric, stat, max and min: passes when at least this fraction of the runs pass"},
    {"scenarios", kString, "", "all", 0, 0,
     "campaign files: the scenarios it judges (a scenario's statistical criteria judge it alone: "
     "refused there)"},
};

}  // namespace campaign_keys

extern const KeySection kCampaignCriterionSection{
    "statistical.criteria[]",
    "one criterion across the seeds (a campaign file's criteria[] alike, "
    "vectors/campaigns/README.md)",
    campaign_keys::kCampaignCriterion};

CampaignCriterion ReadCampaignCriterion(const YamlReader& y) {
  const KeyedReader<campaign_keys::kCampaignCriterion> c(y);
  c.CheckKeys();
  CampaignCriterion k;
  k.scenarios = c.String("scenarios", "");
  char buf[160];
  if (c.Has("pass_fraction")) {
    if (c.Has("metric") || c.Has("stat") || c.Has("max") || c.Has("min"))
      c.Fail("pass_fraction", "a pass_fraction criterion takes no metric, stat, max or min");
    k.kind = "pass_fraction";
    k.min = c.Number("pass_fraction", 1);
    std::snprintf(buf, sizeof buf, "pass fraction >= %g", *k.min);
  } else {
    k.metric = c.String("metric");
    if (std::find(kCriterionMetrics.begin(), kCriterionMetrics.end(), k.metric) ==
            kCriterionMetrics.end() &&
        k.metric.rfind("navd.", 0) != 0) {
      std::string msg = "unknown metric '" + k.metric + "' (one of:";
      for (const auto& m : kCriterionMetrics) msg += " " + m;
      c.Fail("metric", msg + ", navd.<counter>)");
    }
    k.stat = c.Choice("stat", "p95");
    if (c.Has("max") == c.Has("min")) c.Fail("give one of 'max' or 'min'");
    if (c.Has("max")) k.max = c.Number("max", 0);
    if (c.Has("min")) k.min = c.Number("min", 0);
    std::snprintf(buf, sizeof buf, "%s of %s %s %g", k.stat.c_str(), k.metric.c_str(),
                  k.max ? "<=" : ">=", k.max ? *k.max : *k.min);
  }
  k.name = c.String("name", buf);
  return k;
}

}  // namespace hil::harness

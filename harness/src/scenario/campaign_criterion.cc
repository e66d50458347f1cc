// The criterion reader shared by campaign files and scenarios' `statistical:` sections.
#include "hil/harness/scenario/campaign_criterion.h"

#include <algorithm>
#include <cstdio>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

CampaignCriterion ReadCampaignCriterion(const YamlReader& c) {
  c.CheckKeys({"name", "metric", "stat", "max", "min", "pass_fraction", "scenarios"});
  CampaignCriterion k;
  k.scenarios = c.String("scenarios", "");
  char buf[160];
  if (c.Has("pass_fraction")) {
    if (c.Has("metric") || c.Has("stat") || c.Has("max") || c.Has("min"))
      c.Fail("pass_fraction", "a pass_fraction criterion takes no metric, stat, max or min");
    k.kind = "pass_fraction";
    k.min = c.DoubleIn("pass_fraction", 1, 0, 1);
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
    k.stat = c.Choice("stat", "p95", {"mean", "p50", "p95", "max", "min"});
    if (c.Has("max") == c.Has("min")) c.Fail("give one of 'max' or 'min'");
    if (c.Has("max")) k.max = c.DoubleIn("max", 0, -1e12, 1e12);
    if (c.Has("min")) k.min = c.DoubleIn("min", 0, -1e12, 1e12);
    std::snprintf(buf, sizeof buf, "%s of %s %s %g", k.stat.c_str(), k.metric.c_str(),
                  k.max ? "<=" : ">=", k.max ? *k.max : *k.min);
  }
  k.name = c.String("name", buf);
  return k;
}

}  // namespace hil::harness

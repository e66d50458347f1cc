// The default criteria of a run (default_criteria.h): which apply, with which bound.
#include "hil/harness/scenario/default_criteria.h"

#include <cstdio>

#include "hil/harness/report/report.h"

namespace hil::harness {
namespace {

// The scenario's own criterion that judges what the default `d` would, if any.
const Criterion* OwnCriterionOn(const Scenario& s, const DefaultCriterionSpec& d) {
  for (const Criterion& c : s.criteria) {
    if (c.metric != d.metric) continue;
    if (d.kind == DefaultBound::kRatioToBaseline && !c.max_ratio_to_baseline) continue;
    if (d.kind == DefaultBound::kMax && !c.max) continue;
    return &c;
  }
  return nullptr;
}

// A fault of the scenario stops the commands on purpose (controller_stop, command_link_loss).
bool StopsCommandsOnPurpose(const Scenario& s) {
  for (const Fault& f : s.faults.faults) {
    if (f.kind == FaultKind::kControllerStop || f.kind == FaultKind::kCommandLinkLoss) return true;
  }
  return false;
}

// Why `d` cannot judge this run (empty when it can).
std::string NotApplicable(const Scenario& s, const RunReport& r, const DefaultCriterionSpec& d) {
  const std::string key = d.key;
  if (key == "fused_vs_raw" && r.baselines.samples == 0)
    return "no raw GNSS fix in the evaluated window";
  if ((key == "nees_horizontal" || key == "nees_vertical") && r.metrics.samples > 0 &&
      !r.metrics.nees_mean)
    return "the estimator reports no position sigma (pos_std_enu_m)";
  if (key == "controller_commanding" && !s.closed_loop.enabled) return "open loop";
  if (key == "controller_commanding" && StopsCommandsOnPurpose(s))
    return "the scenario stops the controller or cuts its link on purpose (its faults)";
  return "";
}

std::string BoundText(const DefaultCriterionSpec& d, double bound) {
  char buf[128];
  if (d.kind == DefaultBound::kRatioToBaseline)
    std::snprintf(buf, sizeof buf, "%s <= %g x baseline", d.metric, bound);
  else
    std::snprintf(buf, sizeof buf, "%s <= %g", d.metric, bound);
  return buf;
}

}  // namespace

std::vector<Criterion> DefaultCriteriaFor(const Scenario& scenario, const RunReport& report,
                                          std::vector<DefaultCriterionStatus>& status) {
  std::vector<Criterion> out;
  status.clear();
  for (const DefaultCriterionSpec& d : kDefaultCriteria) {
    DefaultCriterionStatus st{d.key, d.metric, "judged", "", std::nullopt};
    const auto it = scenario.default_criteria.find(d.key);
    const DefaultCriterionSetting setting =
        it == scenario.default_criteria.end() ? DefaultCriterionSetting{} : it->second;
    const std::string why_not = NotApplicable(scenario, report, d);
    if (setting.off) {
      st.status = "off";
      st.detail = "turned off by the scenario (default_criteria: {" + st.key + ": off})";
    } else if (const Criterion* own = setting.bound ? nullptr : OwnCriterionOn(scenario, d)) {
      st.status = "superseded";
      st.detail = "the scenario's criterion '" + own->name + "' judges " + d.metric;
    } else if (!why_not.empty()) {
      st.status = "not applicable";
      st.detail = why_not;
    } else {
      const double bound = setting.bound.value_or(d.bound);
      if (setting.bound && *setting.bound != d.bound)
        st.status = *setting.bound > d.bound ? "relaxed" : "tightened";
      st.bound = bound;
      st.detail = BoundText(d, bound);
      Criterion c;
      c.metric = d.metric;
      c.default_key = d.key;
      (d.kind == DefaultBound::kRatioToBaseline ? c.max_ratio_to_baseline : c.max) = bound;
      c.name = "default " + st.key + ": " + st.detail;
      if (st.status != "judged") {
        char def[64];
        std::snprintf(def, sizeof def, " (%s by the scenario from %g)", st.status.c_str(), d.bound);
        c.name += def;
      }
      out.push_back(c);
    }
    status.push_back(st);
  }
  return out;
}

}  // namespace hil::harness

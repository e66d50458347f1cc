// The suite sections of a scenario (owner: acceptance suite). Format:
//
// paper:                       # reference figures a suite report shows beside the run's (a mapping
// or a list)
//   - source: "Paper 000 (Goli et al., 2013), table of methods"
//     metric: horizontal_rmse_m   # a criterion metric, in its unit
//     value: 0.313                # the figure (optional when `finding` says it in words)
//     relation: about             # about (measured), below (an upper bound: "< 11 cm"), above (a
//     lower bound) finding: "diverges"         # the result in words (required without a value)
//     note: "three NEO-5M on a 3 m circle"
//
// short:                       # `hil run --short`, `hil suite --short`: these keys replace the
// top-level ones
//   duration_s: 120            # (any top-level key but name, include, paper and short)
//   faults: [...]
#include <algorithm>

#include "scenario_sections.h"

namespace hil::harness {
namespace {

PaperFigure ReadFigure(const YamlReader& r) {
  if (!r.IsMap()) r.Fail("expected a mapping {source, metric, value, relation, finding, note}");
  r.CheckKeys({"source", "metric", "value", "relation", "finding", "note"});
  PaperFigure p;
  p.source = r.String("source");
  p.metric = r.String("metric");
  // a closed loop's tracking figures (tracking.<field>, as criteria name them) too: paper 003's
  // and the closed-loop papers' figures are the truth's deviation from the path
  if (std::find(kCriterionMetrics.begin(), kCriterionMetrics.end(), p.metric) ==
          kCriterionMetrics.end() &&
      p.metric.rfind("tracking.", 0) != 0 && p.metric.rfind("pass_to_pass.", 0) != 0) {
    std::string msg = "unknown metric '" + p.metric + "' (one of:";
    for (const auto& m : kCriterionMetrics) msg += " " + m;
    r.Fail("metric", msg + ")");
  }
  if (r.Has("value")) p.value = r.DoubleIn("value", 0, -1e9, 1e9);
  p.relation = r.Choice("relation", p.relation, {"about", "below", "above"});
  p.finding = r.String("finding", "");
  p.note = r.String("note", "");
  if (!p.value && p.finding.empty()) r.Fail("a reference figure needs a 'value' or a 'finding'");
  return p;
}

}  // namespace

const std::vector<std::string> kSuiteSectionKeys{"paper", "short", "statistical"};

void ReadSuiteSections(const YamlReader& root, const std::vector<std::string>& top_level_keys,
                       Scenario& s) {
  s.paper.clear();
  if (auto p = root.OptionalChild("paper")) {
    if (p->IsSequence()) {
      if (p->Elements().empty()) p->Fail("expected at least one reference figure");
      for (const YamlReader& item : p->Elements()) s.paper.push_back(ReadFigure(item));
    } else {
      s.paper.push_back(ReadFigure(*p));
    }
  }
  if (auto st = root.OptionalChild("statistical")) {
    st->CheckKeys({"seeds", "criteria"});
    s.statistical_seeds = static_cast<int>(st->Int("seeds", 20, 2, 1000));
    const YamlReader c = st->Child("criteria");
    if (c.Elements().empty()) c.Fail("expected at least one criterion across the seeds");
    for (const YamlReader& item : c.Elements()) {
      CampaignCriterion k = ReadCampaignCriterion(item);
      if (item.Has("scenarios")) item.Fail("scenarios", "a scenario's criteria judge it alone");
      k.scenarios = s.name;
      s.statistical_criteria.push_back(k);
    }
  }
  if (auto sh = root.OptionalChild("short")) {
    if (!sh->IsMap() || sh->node().size() == 0)
      sh->Fail("expected a mapping of top-level keys (e.g. duration_s: 120)");
    std::vector<std::string> allowed;
    for (const auto& k : top_level_keys) {
      if (k != "name" && k != "include" && k != "paper" && k != "short") allowed.push_back(k);
    }
    sh->CheckKeys(allowed);
    s.has_short_form = true;
  }
}

void ApplyShortForm(YamlReader& root) {
  const auto sh = root.OptionalChild("short");
  if (!sh || !sh->IsMap()) return;  // an invalid section is reported by ReadSuiteSections
  YAML::Node doc = root.node();     // shares the document: assignments below change the root
  for (const auto& kv : sh->node()) {
    const std::string key = kv.first.Scalar();
    if (key == "name" || key == "include" || key == "paper" || key == "short")
      continue;  // rejected later
    doc[key] = kv.second;
  }
}

}  // namespace hil::harness

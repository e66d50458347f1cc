// The suite sections of a scenario (owner: acceptance suite): `paper:` (reference figures),
// `statistical:` (criteria across seeds), their tables below (docs/scenario_reference.md), and
// `short:` (a row of the top level's table, scenario_root_keys.h):
//
// paper:
//   - {source: "Paper 000 (Goli et al., 2013), table of methods", metric: horizontal_rmse_m,
//      value: 0.313, relation: about, note: "three NEO-5M on a 3 m circle"}
// short:                       # `hil run --short`: these keys replace the top-level ones
//   duration_s: 120
#include <algorithm>

#include "scenario_sections.h"

namespace hil::harness {
namespace suite_keys {  // named: the unity build joins the readers' files

using enum KeyType;

inline constexpr std::string_view kRelations[] = {"about", "below", "above"};

inline constexpr ScenarioKey kFigure[] = {
    {"source", kString, "", "required", 0, 0,
     "where the figure is published (\"Paper 000 (Goli et al., 2013), table of methods\")"},
    {"metric", kString, "", "required", 0, 0,
     "the criterion metric it compares with (criteria[].metric's, tracking.*, pass_to_pass.*, "
     "rtk_rover.*), "
     "in its unit"},
    {"value", kNumber, "", "none (then finding)", -1e9, 1e9, "the figure"},
    {"relation", kChoice, "", "about", 0, 0,
     "about: a measured value; below: an upper bound (\"< 11 cm\"); above: a lower bound",
     kRelations},
    {"finding", kString, "", "\"\" (required without value)", 0, 0, "the result in words"},
    {"note", kString, "", "\"\"", 0, 0, "what the figure was measured with"},
};

inline constexpr ScenarioKey kStatistical[] = {
    {"seeds", kInteger, "", "20", 2, 1000, "seeds the suite runs the scenario with", kNoChoices,
     kAnyRange, "ours: issue 43's \"mean and p95 over ≥ 20 seeds\""},
    {"criteria", kList, "", "required (≥ 1)", 0, 0,
     "criteria across the seeds (statistical.criteria[])"},
};

}  // namespace suite_keys

namespace {

using suite_keys::kFigure;
using suite_keys::kStatistical;

PaperFigure ReadFigure(const YamlReader& y) {
  if (!y.IsMap()) y.Fail("expected a mapping {source, metric, value, relation, finding, note}");
  const KeyedReader<kFigure> r(y);
  r.CheckKeys();
  PaperFigure p;
  p.source = r.String("source");
  p.metric = r.String("metric");
  // any metric a criterion may name: a closed loop's tracking figures (tracking.<field>) too,
  // since paper 003's and the closed-loop papers' figures are the truth's deviation from the path
  if (!IsCriterionMetric(p.metric)) {
    std::string msg = "unknown metric '" + p.metric + "' (one of:";
    for (const auto& m : kCriterionMetrics) msg += " " + m;
    for (const auto& x : kCriterionMetricPrefixes) msg += " " + x + "*";
    r.Fail("metric", msg + ")");
  }
  if (r.Has("value")) p.value = r.Number("value", 0);
  p.relation = r.Choice("relation", p.relation);
  p.finding = r.String("finding", "");
  p.note = r.String("note", "");
  if (!p.value && p.finding.empty()) r.Fail("a reference figure needs a 'value' or a 'finding'");
  return p;
}

void ReadStatistical(const YamlReader& y, Scenario& s) {
  const KeyedReader<kStatistical> st(y);
  st.CheckKeys();
  s.statistical_seeds = static_cast<int>(st.Integer("seeds", 20));
  const YamlReader c = st.Child("criteria");
  if (c.Elements().empty()) c.Fail("expected at least one criterion across the seeds");
  for (const YamlReader& item : c.Elements()) {
    CampaignCriterion k = ReadCampaignCriterion(item);
    if (item.Has("scenarios")) item.Fail("scenarios", "a scenario's criteria judge it alone");
    k.scenarios = s.name;
    s.statistical_criteria.push_back(k);
  }
}

}  // namespace

extern const KeySection kPaperSection{
    "paper[]",
    "a published reference figure a suite report shows beside the run's (paper: one mapping or a "
    "list)",
    kFigure};
extern const KeySection kStatisticalSection{
    "statistical",
    "a claim about a distribution: the seeds a suite runs the scenario with and its criteria "
    "across them",
    kStatistical};

const std::vector<std::string> kSuiteSectionKeys{"paper", "statistical"};

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
  if (auto st = root.OptionalChild("statistical")) ReadStatistical(*st, s);
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

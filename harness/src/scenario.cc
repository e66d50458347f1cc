#include "hil/harness/scenario.h"

#include <fstream>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/yaml_reader.h"
#include "scenario_sections.h"

namespace hil::harness {

extern const char* const kDefaultScenarioYaml;  // generated from vectors/scenarios/default.yaml

namespace {

void ReadEstimator(const YamlReader& r, EstimatorSpec& e) {
  r.CheckKeys({"command", "output", "navd_mode", "silence_timeout_s"});
  e.command = r.String("command", e.command);
  e.output = r.Choice("output", e.output, {"json_stdout"});
  e.navd_mode = r.Choice("navd_mode", e.navd_mode, {"gnss_only"});
  e.silence_timeout_s = r.DoubleIn("silence_timeout_s", e.silence_timeout_s, 0.5, 3600);
}

std::vector<Criterion> ReadCriteria(const YamlReader& r) {
  std::vector<Criterion> out;
  for (const YamlReader& c : r.Elements()) {
    c.CheckKeys({"metric", "max", "max_ratio_to_baseline", "name"});
    Criterion k;
    k.metric = c.Choice("metric", "", {"horizontal_rmse_m", "cep50_m", "cep95_m", "max_horizontal_error_m",
                                       "vertical_rmse_m", "velocity_rmse_mps", "heading_rmse_deg"});
    if (c.Has("max")) k.max = c.DoubleIn("max", 0, 0, 1e9);
    if (c.Has("max_ratio_to_baseline")) k.max_ratio_to_baseline = c.DoubleIn("max_ratio_to_baseline", 0, 0, 1e3);
    if (!k.max && !k.max_ratio_to_baseline) c.Fail("a criterion needs 'max' or 'max_ratio_to_baseline'");
    if (k.max && k.max_ratio_to_baseline) c.Fail("give 'max' or 'max_ratio_to_baseline', not both");
    char buf[128];
    if (k.max) std::snprintf(buf, sizeof buf, "%s <= %g", k.metric.c_str(), *k.max);
    else std::snprintf(buf, sizeof buf, "%s <= %g x baseline", k.metric.c_str(), *k.max_ratio_to_baseline);
    k.name = c.String("name", buf);
    out.push_back(k);
  }
  return out;
}

Scenario FromReader(const YamlReader& root) {
  std::vector<std::string> keys{"name", "description", "start_utc", "duration_s", "seed", "estimator", "criteria"};
  for (const auto* section : {&kTruthSectionKeys, &kGnssSectionKeys, &kMcuSectionKeys, &kCanSectionKeys}) {
    keys.insert(keys.end(), section->begin(), section->end());
  }
  root.CheckKeys(keys);
  Scenario s;
  s.file = root.file();
  s.name = root.String("name");
  s.description = root.String("description", "");
  try {
    s.start_unix_ns = gnss::ParseIsoUtc(root.String("start_utc", "2013-06-10T08:00:00Z"));
  } catch (const std::invalid_argument& e) {
    root.Fail("start_utc", e.what());
  }
  s.duration_s = root.DoubleIn("duration_s", s.duration_s, 1, 7 * 86400);
  s.seed = static_cast<std::uint64_t>(root.Int("seed", 1, 0, INT64_MAX));
  ReadTruthSections(root, s.truth);
  ReadGnssSection(root, s.gnss);
  ReadMcuSection(root, s.mcu);
  s.mcu.config.start_unix_ns = s.start_unix_ns;
  // seed 000: the IMU runs 10 times as fast as the GPS
  if (s.mcu.imu_rate_is_default) s.mcu.config.imu_rate_hz = 10.0 * s.gnss.rate_hz;
  ReadCanSection(root, s.can);
  if (auto e = root.OptionalChild("estimator")) ReadEstimator(*e, s.estimator);
  if (auto c = root.OptionalChild("criteria")) s.criteria = ReadCriteria(*c);
  return s;
}

}  // namespace

Scenario LoadScenario(const std::string& path) { return FromReader(YamlReader::LoadFile(path)); }

Scenario ParseScenario(const std::string& text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(name, e.mark.line + 1, "", "YAML syntax error: " + e.msg);
  }
  if (!root.IsMap()) throw ScenarioError(name, 1, "", "the document must be a mapping of keys");
  return FromReader(YamlReader(root, name, ""));
}

Scenario LoadDefaultScenario() { return ParseScenario(kDefaultScenarioYaml, "<embedded default scenario>"); }

}  // namespace hil::harness

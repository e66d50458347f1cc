#include "hil/harness/scenario/scenario.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/scenario/scenario_overrides.h"
#include "hil/harness/scenario/scenario_reader.h"
#include "hil/harness/scenario/yaml_reader.h"

#include "scenario_root_keys.h"
#include "scenario_sections.h"

namespace hil::harness {

extern const char* const kDefaultScenarioYaml;  // generated from vectors/scenarios/default.yaml

const std::vector<std::string> kCriterionMetrics{"horizontal_rmse_m",
                                                 "horizontal_rmse_to_raw",
                                                 "cep50_m",
                                                 "cep95_m",
                                                 "max_horizontal_error_m",
                                                 "vertical_rmse_m",
                                                 "velocity_rmse_mps",
                                                 "heading_rmse_deg",
                                                 "cross_track_rmse_m",
                                                 "cross_track_p95_m",
                                                 "cross_track_max_m",
                                                 "output_rate_hz",
                                                 "max_lateral_deviation_m",
                                                 "max_heading_deviation_deg",
                                                 "latency_p99_ms",
                                                 "jitter_p99_ms",
                                                 "outage_max_horizontal_error_m",
                                                 "reconvergence_time_s",
                                                 "nees_mean",
                                                 "nees_horizontal_mean",
                                                 "nees_vertical_mean",
                                                 "solutions_missing_fraction",
                                                 "fault_recovery_time_s",
                                                 "fault_injections_min",
                                                 "outage_max_east_error_m",
                                                 "outage_max_north_error_m",
                                                 "outage_max_up_error_m",
                                                 "outage_max_enu_error_m"};

const std::vector<std::string> kCriterionMetricPrefixes{"navd.", "tracking.", "pass_to_pass.",
                                                        "closed_loop.", "rtk_rover."};

bool IsCriterionMetric(const std::string& metric) {
  if (std::find(kCriterionMetrics.begin(), kCriterionMetrics.end(), metric) !=
      kCriterionMetrics.end())
    return true;
  return std::any_of(kCriterionMetricPrefixes.begin(), kCriterionMetricPrefixes.end(),
                     [&metric](const std::string& p) { return metric.rfind(p, 0) == 0; });
}

namespace {

// the tables read here (a using-declaration each: the unity build joins the readers' files)
using root_keys::kCriterion;
using root_keys::kEstimator;
using root_keys::kEvaluation;
using root_keys::kRoot;

// A mapping of navd.conf keys of one section to scalar values, in file order.
std::vector<std::pair<std::string, std::string>> ReadNavdKeys(
    const YamlReader& f, const char* section, const std::vector<std::string>& reserved = {}) {
  if (!f.IsMap())
    f.Fail(std::string("expected a mapping of navd [") + section + "] keys to values");
  std::vector<std::pair<std::string, std::string>> keys;
  for (const auto& kv : f.node()) {
    const std::string key = kv.first.Scalar();
    if (key.empty() || key.find_first_of(" =[]#\n") != std::string::npos)
      f.Fail(key, "not a navd key");
    for (const auto& r : reserved) {
      if (key == r) f.Fail(key, "set by hil from the scenario's devices");
    }
    if (!kv.second.IsScalar())
      f.Fail(key, "expected a single value (navd lists are comma-separated strings)");
    keys.emplace_back(key, kv.second.Scalar());
  }
  return keys;
}

void ReadEstimator(const YamlReader& y, EstimatorSpec& e) {
  const KeyedReader<kEstimator> r(y);
  r.CheckKeys();
  e.reference_point = r.Choice("reference_point", e.reference_point);
  e.command = r.String("command", e.command);
  e.output = r.Choice("output", e.output);
  e.navd_mode = r.Choice("navd_mode", e.navd_mode);
  if (auto f = r.OptionalChild("navd_filter")) e.navd_filter = ReadNavdKeys(*f, "filter");
  if (auto f = r.OptionalChild("navd_input")) {
    e.navd_input = ReadNavdKeys(
        *f, "input", {"gnss_device", "gnss_baud", "imu_device", "imu_baud", "imu_format"});
  }
  e.silence_timeout_s = r.Number("silence_timeout_s", e.silence_timeout_s);
  e.startup_s = r.Number("startup_s", e.startup_s);
}

std::vector<Criterion> ReadCriteria(const YamlReader& r) {
  std::vector<Criterion> out;
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kCriterion> c(y);
    c.CheckKeys();
    Criterion k;
    k.metric = c.String("metric");
    if (!IsCriterionMetric(k.metric)) {
      std::string msg = "unknown metric '" + k.metric + "' (one of:";
      for (const auto& m : kCriterionMetrics) msg += " " + m;
      for (const auto& p : kCriterionMetricPrefixes) msg += " " + p + "*";
      c.Fail("metric", msg + ")");
    }
    if (c.Has("max")) k.max = c.Number("max", 0);
    if (c.Has("min")) k.min = c.Number("min", 0);
    if (c.Has("max_ratio_to_baseline"))
      k.max_ratio_to_baseline = c.Number("max_ratio_to_baseline", 0);
    const int given = (k.max ? 1 : 0) + (k.min ? 1 : 0) + (k.max_ratio_to_baseline ? 1 : 0);
    if (given == 0) c.Fail("a criterion needs 'max', 'min' or 'max_ratio_to_baseline'");
    if (given > 1) c.Fail("give one of 'max', 'min' or 'max_ratio_to_baseline'");
    char buf[128];
    if (k.max)
      std::snprintf(buf, sizeof buf, "%s <= %g", k.metric.c_str(), *k.max);
    else if (k.min)
      std::snprintf(buf, sizeof buf, "%s >= %g", k.metric.c_str(), *k.min);
    else
      std::snprintf(buf, sizeof buf, "%s <= %g x baseline", k.metric.c_str(),
                    *k.max_ratio_to_baseline);
    k.name = c.String("name", buf);
    out.push_back(k);
  }
  return out;
}

// `default_criteria: {KEY: off | NUMBER}` (default_criteria.h).
std::map<std::string, DefaultCriterionSetting> ReadDefaultCriteria(const YamlReader& r) {
  if (!r.IsMap()) r.Fail("expected a mapping of default criterion keys to `off` or a number");
  std::vector<std::string> keys;
  for (const DefaultCriterionSpec& d : kDefaultCriteria) keys.emplace_back(d.key);
  r.CheckKeys(keys);
  std::map<std::string, DefaultCriterionSetting> out;
  for (const std::string& key : keys) {
    if (!r.Has(key)) continue;
    DefaultCriterionSetting setting;
    if (r.String(key) == "off")
      setting.off = true;
    else
      setting.bound = r.DoubleIn(key, 0, 0, 1e9);
    out[key] = setting;
  }
  return out;
}

// navd's multi_gnss mode reads the gnss receivers only: a rover that would feed navd is refused
// rather than left out in silence (navd_gnss_source.h).
void CheckRoverInput(const YamlReader& root, const Scenario& s) {
  if (!s.zed_f9p.enabled || !s.zed_f9p.navd_input) return;
  if (s.estimator.navd_mode != NavdMode::kMultiGnss) return;
  root.OptionalChild("zed_f9p")->Fail(
      "navd_input", "navd's multi_gnss mode reads the gnss receivers; set navd_input: false");
}

Scenario FromReader(const YamlReader& root, const DeviceSections& devices) {
  std::vector<std::string> keys = ScenarioOwnKeys();
  keys.insert(keys.end(), devices.keys.begin(), devices.keys.end());
  root.CheckKeys(keys);
  Scenario s;
  s.file = root.file();
  const KeyedReader<kRoot> top(root);
  s.name = top.String("name");
  s.description = top.String("description", "");
  try {
    s.start_utc = gnss::ParseIsoUtc(top.String("start_utc", kDefaultStartUtc));
  } catch (const std::invalid_argument& e) {
    top.Fail("start_utc", e.what());
  }
  s.duration_s = top.Number("duration_s", s.duration_s);
  s.seed = static_cast<std::uint64_t>(top.Integer("seed", 1));
  ReadTruthSections(root, s.truth);
  ReadCanSection(root, s.can);
  ReadGreenhouseSection(root, s);
  devices.read(root, s);  // the device table's rows, in table order
  ReadClosedLoopSection(root, s);
  ReadSuiteSections(root, keys, s);
  if (auto e = top.OptionalChild("estimator")) ReadEstimator(*e, s.estimator);
  CheckCanUse(root, s);
  CheckRoverInput(root, s);
  if (auto c = top.OptionalChild("criteria")) s.criteria = ReadCriteria(*c);
  if (auto d = top.OptionalChild("default_criteria")) s.default_criteria = ReadDefaultCriteria(*d);
  if (auto f = top.OptionalChild("faults")) s.faults = ReadFaultTimeline(*f, s.duration_s);
  if (auto y = top.OptionalChild("evaluation")) {
    const KeyedReader<kEvaluation> ev(*y);
    ev.CheckKeys();
    s.evaluate_from_s = ev.NumberIn("from_s", 0, 0, s.duration_s);
    s.reconverged_error_m = ev.Number("reconverged_error_m", s.reconverged_error_m);
  }
  return s;
}

}  // namespace

std::vector<std::string> ScenarioLibraryDirs() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("HIL_SCENARIO_LIB")) {
    std::stringstream ss(env);
    for (std::string d; std::getline(ss, d, ':');) {
      if (!d.empty()) dirs.push_back(d);
    }
  }
  // an installed hil (cmake --install, the Debian package): PREFIX/share/hil/scenarios/lib, ahead
  // of the build's checkout (an installed hil reads its own pieces, whatever checkout is left)
  std::error_code ec;
  const std::filesystem::path installed =
      std::filesystem::read_symlink("/proc/self/exe", ec).parent_path().parent_path() /
      "share/hil/scenarios/lib";
  if (!ec && std::filesystem::is_directory(installed, ec)) dirs.push_back(installed.string());
  dirs.emplace_back(HIL_SCENARIO_LIB_DIR);
  return dirs;
}

extern const KeySection kRootSection{
    "", "the top level: the loader's own keys (the other top-level keys are sections below)",
    kRoot};
extern const KeySection kEstimatorSection{"estimator", "the estimator under test", kEstimator};
extern const KeySection kCriterionSection{"criteria[]", "one pass/fail bound", kCriterion};
extern const KeySection kEvaluationSection{"evaluation", "what is scored", kEvaluation};

std::vector<std::string> ScenarioOwnKeys() {
  std::vector<std::string> keys;
  for (const ScenarioKey& k : kRoot) keys.emplace_back(k.name);
  for (const auto* section : {&kTruthSectionKeys, &kCanSectionKeys, &kGreenhouseSectionKeys,
                              &kSuiteSectionKeys, &kClosedLoopSectionKeys}) {
    keys.insert(keys.end(), section->begin(), section->end());
  }
  return keys;
}

Scenario LoadScenarioFile(const std::string& path, bool short_form,
                          const std::vector<ScenarioOverride>& overrides,
                          const DeviceSections& devices) {
  YamlReader root = YamlReader::LoadFile(path);
  if (short_form)
    ApplyShortForm(root);  // before the includes: a replaced key is the document's own
  root.ResolveIncludes(std::filesystem::path(path).parent_path().string(), ScenarioLibraryDirs());
  ApplyOverrides(root, overrides);  // after them: a field an include gave can be set too
  Scenario s = FromReader(root, devices);
  s.short_form = short_form && s.has_short_form;
  return s;
}

Scenario ParseScenarioText(const std::string& text, const std::string& name,
                           const DeviceSections& devices) {
  YamlReader reader = YamlReader::FromText(text, name);
  reader.ResolveIncludes(".", ScenarioLibraryDirs());
  return FromReader(reader, devices);
}

const char* DefaultScenarioText() { return kDefaultScenarioYaml; }

}  // namespace hil::harness

#include "hil/harness/scenario.h"

#include <fstream>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/yaml_reader.h"

namespace hil::harness {

extern const char* const kDefaultScenarioYaml;  // generated from vectors/scenarios/default.yaml

namespace {

constexpr double kKmhToMps = 1.0 / 3.6;

void ReadOrigin(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"lat_deg", "lon_deg", "height_m"});
  t.origin.lat_deg = r.DoubleIn("lat_deg", 0, -90, 90);
  t.origin.lon_deg = r.DoubleIn("lon_deg", 0, -180, 180);
  t.origin.height_m = r.DoubleIn("height_m", 0, -500, 9000);
  if (!r.Has("lat_deg")) r.Fail("missing required key 'lat_deg'");
  if (!r.Has("lon_deg")) r.Fail("missing required key 'lon_deg'");
}

void ReadPath(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"type", "start_enu_m", "heading_deg", "speed_kmh", "speed_mps", "steer_deg"});
  r.Choice("type", "line", {"line"});
  const auto start = r.Doubles("start_enu_m", 2, {0.0, 0.0});
  t.start_p_N_m = Eigen::Vector2d(start[0], start[1]);
  t.heading_deg = r.DoubleIn("heading_deg", 0, -360, 360);
  if (r.Has("speed_kmh") && r.Has("speed_mps")) r.Fail("speed_mps", "give speed_kmh or speed_mps, not both");
  t.speed_mps = r.Has("speed_kmh") ? r.DoubleIn("speed_kmh", 0, 0, 100) * kKmhToMps : r.DoubleIn("speed_mps", t.speed_mps, 0, 30);
  t.steer_deg = r.DoubleIn("steer_deg", 0, -45, 45);
}

void ReadVehicle(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"model", "wheelbase_m", "speed_lag_s"});
  r.Choice("model", "bicycle", {"bicycle"});
  t.wheelbase_m = r.DoubleIn("wheelbase_m", t.wheelbase_m, 0.1, 20);
  t.speed_lag_s = r.DoubleIn("speed_lag_s", t.speed_lag_s, 0.01, 60);
}

void ReadGnss(const YamlReader& r, GnssDeviceSpec& g) {
  r.CheckKeys({"profile", "baud", "link", "rate_hz", "output_lag_s", "tx_buffer_bytes", "errors", "antenna_lever_arm_m"});
  g.profile = r.Choice("profile", g.profile, {"neo-5m"});
  g.baud = static_cast<int>(r.Int("baud", g.baud, 1200, 921600));
  g.link = r.String("link", g.link);
  if (g.link.empty() || g.link.find('/') != std::string::npos) r.Fail("link", "must be a plain file name such as ttyGPS");
  g.rate_hz = r.DoubleIn("rate_hz", g.rate_hz, 0.1, 20);
  g.output_lag_s = r.DoubleIn("output_lag_s", g.output_lag_s, 0, 0.9);
  g.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 1024, 64, 1 << 20));
  const auto lever = r.Doubles("antenna_lever_arm_m", 3, {0, 0, 0});
  g.model.p_BA_B_m = Eigen::Vector3d(lever[0], lever[1], lever[2]);
  if (auto e = r.OptionalChild("errors")) {
    e->CheckKeys({"horizontal_sigma_m", "vertical_sigma_m", "correlation_time_s", "velocity_sigma_mps"});
    g.model.horizontal_sigma_m = e->DoubleIn("horizontal_sigma_m", g.model.horizontal_sigma_m, 0, 100);
    g.model.vertical_sigma_m = e->DoubleIn("vertical_sigma_m", g.model.vertical_sigma_m, 0, 100);
    g.model.correlation_time_s = e->DoubleIn("correlation_time_s", g.model.correlation_time_s, 0.01, 3600);
    g.model.velocity_sigma_mps = e->DoubleIn("velocity_sigma_mps", g.model.velocity_sigma_mps, 0, 10);
  }
}

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
  root.CheckKeys({"name", "description", "start_utc", "duration_s", "seed", "origin", "vehicle", "path",
                  "gnss", "estimator", "criteria"});
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
  ReadOrigin(root.Child("origin"), s.truth);
  if (auto v = root.OptionalChild("vehicle")) ReadVehicle(*v, s.truth);
  if (auto p = root.OptionalChild("path")) ReadPath(*p, s.truth);
  if (auto g = root.OptionalChild("gnss")) ReadGnss(*g, s.gnss);
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

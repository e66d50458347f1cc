#include "scenario_sections.h"

namespace hil::harness {
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

}  // namespace

const std::vector<std::string> kTruthSectionKeys{"origin", "vehicle", "path"};

void ReadTruthSections(const YamlReader& root, truth::TruthConfig& t) {
  ReadOrigin(root.Child("origin"), t);
  if (auto v = root.OptionalChild("vehicle")) ReadVehicle(*v, t);
  if (auto p = root.OptionalChild("path")) ReadPath(*p, t);
}

}  // namespace hil::harness

#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/angles.h"

#include "scenario_sections.h"

namespace hil::harness {
namespace {

constexpr double kKmhToMps = 1.0 / 3.6;

void ReadOrigin(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"lat_deg", "lon_deg", "height_m"});
  if (!r.Has("lat_deg")) r.Fail("missing required key 'lat_deg'");
  if (!r.Has("lon_deg")) r.Fail("missing required key 'lon_deg'");
  t.origin.lat_deg = r.DoubleIn("lat_deg", 0, -90, 90);
  t.origin.lon_deg = r.DoubleIn("lon_deg", 0, -180, 180);
  t.origin.height_m = r.DoubleIn("height_m", 0, -500, 9000);
}

void ReadVehicle(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"model", "wheelbase_m", "track_m", "max_steer_deg", "max_steer_rate_dps",
               "steer_lag_s", "speed_lag_s", "yaw_rate_lag_s", "max_yaw_rate_dps",
               "slip_gain_rad_per_mps2", "speed_variation"});
  const std::string model = r.Choice("model", "bicycle", {"bicycle", "tractor", "diff_drive"});
  truth::VehicleParams p = model == "tractor"      ? truth::VehicleParams::Tractor()
                           : model == "diff_drive" ? truth::VehicleParams::DiffDrive()
                                                   : truth::VehicleParams::GreenhousePlatform();
  if (model == "diff_drive") {
    for (const char* k : {"wheelbase_m", "max_steer_deg", "max_steer_rate_dps", "steer_lag_s"}) {
      if (r.Has(k)) r.Fail(k, "not a parameter of the diff_drive model");
    }
  } else {
    for (const char* k : {"yaw_rate_lag_s", "max_yaw_rate_dps"}) {
      if (r.Has(k)) r.Fail(k, "only a parameter of the diff_drive model");
    }
  }
  p.wheelbase_m = r.DoubleIn("wheelbase_m", p.wheelbase_m, 0.1, 20);
  p.track_m = r.DoubleIn("track_m", p.track_m, 0.1, 10);
  p.max_steer_deg = r.DoubleIn("max_steer_deg", p.max_steer_deg, 1, 60);
  p.max_steer_rate_dps = r.DoubleIn("max_steer_rate_dps", p.max_steer_rate_dps, 0.5, 360);
  p.steer_lag_s = r.DoubleIn("steer_lag_s", p.steer_lag_s, 0.01, 10);
  p.speed_lag_s = r.DoubleIn("speed_lag_s", p.speed_lag_s, 0.01, 60);
  p.yaw_rate_lag_s = r.DoubleIn("yaw_rate_lag_s", p.yaw_rate_lag_s, 0.01, 10);
  p.max_yaw_rate_dps = r.DoubleIn("max_yaw_rate_dps", p.max_yaw_rate_dps, 1, 360);
  p.slip_gain_rad_per_mps2 = r.DoubleIn("slip_gain_rad_per_mps2", p.slip_gain_rad_per_mps2, 0, 0.2);
  if (auto sv = r.OptionalChild("speed_variation")) {
    sv->CheckKeys({"std_percent", "correlation_time_s", "seed"});
    p.speed_variation_std = sv->DoubleIn("std_percent", 0, 0, 50) / 100.0;
    p.speed_variation_tau_s =
        sv->DoubleIn("correlation_time_s", p.speed_variation_tau_s, 0.1, 3600);
    p.speed_variation_seed = static_cast<std::uint64_t>(sv->Int("seed", 1, 0, INT64_MAX));
  }
  t.vehicle = p;
}

Eigen::Vector2d Point(const YamlReader& r, const std::string& key, Eigen::Vector2d fallback) {
  const auto v = r.Doubles(key, 2, {fallback.x(), fallback.y()});
  for (double x : v) {
    if (!(std::abs(x) <= 1e6)) r.Fail(key, "coordinates must be within 1000 km of the origin");
  }
  return {v[0], v[1]};
}

double Speed(const YamlReader& r, double fallback) {
  if (r.Has("speed_kmh") && r.Has("speed_mps"))
    r.Fail("speed_mps", "give speed_kmh or speed_mps, not both");
  return r.Has("speed_kmh") ? r.DoubleIn("speed_kmh", 0, 0, 100) * kKmhToMps
                            : r.DoubleIn("speed_mps", fallback, 0, 30);
}

std::vector<truth::PathVertex> ReadWaypoints(const YamlReader& list) {
  std::vector<truth::PathVertex> out;
  for (const YamlReader& w : list.Elements()) {
    truth::PathVertex v;
    if (w.IsSequence()) {
      const YAML::Node& n = w.node();
      if (n.size() != 2)
        w.Fail("a waypoint is [east_m, north_m] or {enu_m: [e, n], speed_mps, stop_s}");
      try {
        v.p_N_m = {n[0].as<double>(), n[1].as<double>()};
      } catch (const YAML::Exception&) {
        w.Fail("expected two numbers");
      }
      if (!v.p_N_m.allFinite())
        w.Fail("expected two finite numbers, got [" + n[0].Scalar() + ", " + n[1].Scalar() + "]");
      if (!(v.p_N_m.cwiseAbs().maxCoeff() <= 1e6))
        w.Fail("coordinates must be within 1000 km of the origin");
    } else {
      w.CheckKeys({"enu_m", "speed_mps", "speed_kmh", "stop_s"});
      if (!w.Has("enu_m")) w.Fail("missing required key 'enu_m'");
      v.p_N_m = Point(w, "enu_m", {0, 0});
      if (w.Has("speed_mps") || w.Has("speed_kmh")) v.speed_mps = Speed(w, 0);
      v.stop_s = w.DoubleIn("stop_s", 0, 0, 86400);
    }
    out.push_back(v);
  }
  if (out.size() < 2) list.Fail("a path needs at least 2 waypoints");
  for (std::size_t i = 0; i + 1 < out.size(); ++i) {
    if ((out[i + 1].p_N_m - out[i].p_N_m).norm() < 1e-3)
      list.Elements()[i + 1].Fail("repeats the previous waypoint");
  }
  return out;
}

// speed_profile: steps at increasing times, each with its speed.
void ReadSpeedProfile(const YamlReader& prof, std::vector<truth::SpeedStep>& out) {
  double last = -1;
  for (const YamlReader& step : prof.Elements()) {
    step.CheckKeys({"t_s", "speed_mps", "speed_kmh"});
    truth::SpeedStep s;
    s.t_s = step.DoubleIn("t_s", 0, 0, 7 * 86400);
    if (!step.Has("t_s")) step.Fail("missing required key 't_s'");
    if (s.t_s <= last) step.Fail("t_s", "speed profile times must increase");
    last = s.t_s;
    if (!step.Has("speed_mps") && !step.Has("speed_kmh"))
      step.Fail("missing 'speed_mps' or 'speed_kmh'");
    s.speed_mps = Speed(step, 0);
    out.push_back(s);
  }
}

// A boustrophedon path, its turns no tighter than vehicle `v` can steer.
truth::Path ReadBoustrophedon(const YamlReader& r, const truth::VehicleParams& v) {
  truth::BoustrophedonSpec b;
  b.start_p_N_m = Point(r, "row_start_enu_m", {0, 0});
  b.heading_deg = r.DoubleIn("row_heading_deg", 0, -360, 360);
  b.row_length_m = r.DoubleIn("row_length_m", 100, 1, 1e5);
  b.row_spacing_m = r.DoubleIn("row_spacing_m", 7.5, 0.2, 1000);
  b.rows = static_cast<int>(r.Int("rows", 4, 1, 10000));
  const double r_min = v.model == truth::VehicleParams::Model::kDiffDrive
                           ? 0.0
                           : v.wheelbase_m / std::tan(v.max_steer_deg * kDeg);
  b.turn_radius_m =
      r.DoubleIn("turn_radius_m", std::max(r_min * 1.05, b.row_spacing_m / 2 * 0.999), 0.1, 1000);
  if (b.turn_radius_m < r_min) {
    r.Fail("turn_radius_m",
           "below the vehicle's minimum turning radius " + std::to_string(r_min) + " m");
  }
  if (b.row_spacing_m < 2 * b.turn_radius_m) {
    r.Fail("row_spacing_m", "row spacing must be at least twice the turn radius (" +
                                std::to_string(b.turn_radius_m) + " m)");
  }
  b.first_turn_right = r.Choice("first_turn", "right", {"right", "left"}) == "right";
  if (r.Has("turn_speed_mps")) b.turn_speed_mps = r.DoubleIn("turn_speed_mps", 0, 0.05, 30);
  return truth::MakeBoustrophedon(b);
}

void ReadPath(const YamlReader& r, truth::TruthConfig& t) {
  const std::string type = r.Choice(
      "type", "line", {"line", "ab_line", "waypoints", "rectangle", "boustrophedon", "circle"});
  std::vector<std::string> keys{"type",          "speed_kmh",   "speed_mps",
                                "speed_profile", "start_enu_m", "heading_deg"};
  const auto allow = [&keys](std::initializer_list<const char*> more) {
    keys.insert(keys.end(), more.begin(), more.end());
  };
  const bool diff_drive = t.vehicle.model == truth::VehicleParams::Model::kDiffDrive;
  if (type == "line") allow({diff_drive ? "yaw_rate_dps" : "steer_deg"});
  if (type == "ab_line") allow({"a_enu_m", "b_enu_m"});
  if (type == "waypoints") allow({"points"});
  if (type == "rectangle")
    allow({"corner_enu_m", "width_m", "height_m", "side_heading_deg", "clockwise", "laps"});
  if (type == "boustrophedon")
    allow({"row_start_enu_m", "row_heading_deg", "row_length_m", "row_spacing_m", "rows",
           "turn_radius_m", "first_turn", "turn_speed_mps"});
  if (type == "circle")
    allow({"centre_enu_m", "radius_m", "start_bearing_deg", "direction", "laps"});
  if (type != "line")
    allow({"lookahead_m", "guidance_rate_hz", "stop_decel_mps2", "turn_in_place_deg"});
  r.CheckKeys(keys);

  t.speed_mps = Speed(r, t.speed_mps);
  if (auto prof = r.OptionalChild("speed_profile")) ReadSpeedProfile(*prof, t.speed_profile);
  if (r.Has("start_enu_m")) t.start_p_N_m = Point(r, "start_enu_m", {0, 0});
  if (r.Has("heading_deg")) t.heading_deg = r.DoubleIn("heading_deg", 0, -360, 360);
  if (type == "line") {
    if (diff_drive)
      t.yaw_rate_dps =
          r.DoubleIn("yaw_rate_dps", 0, -t.vehicle.max_yaw_rate_dps, t.vehicle.max_yaw_rate_dps);
    else
      t.steer_deg = r.DoubleIn("steer_deg", 0, -t.vehicle.max_steer_deg, t.vehicle.max_steer_deg);
    return;
  }
  truth::GuidanceConfig& g = t.guidance;
  g.lookahead_m = r.DoubleIn("lookahead_m", type == "boustrophedon" ? 3.0 : g.lookahead_m, 0.1, 50);
  g.rate_hz = r.DoubleIn("guidance_rate_hz", g.rate_hz, 1, 1000);
  g.stop_decel_mps2 = r.DoubleIn("stop_decel_mps2", g.stop_decel_mps2, 0.01, 10);
  g.turn_in_place_deg = r.DoubleIn("turn_in_place_deg", g.turn_in_place_deg, 1, 180);
  try {
    if (type == "ab_line") {
      if (!r.Has("a_enu_m") || !r.Has("b_enu_m"))
        r.Fail("an ab_line needs 'a_enu_m' and 'b_enu_m'");
      const Eigen::Vector2d a = Point(r, "a_enu_m", {0, 0}), b = Point(r, "b_enu_m", {0, 0});
      if ((b - a).norm() < 0.1) r.Fail("b_enu_m", "A and B must be at least 0.1 m apart");
      t.path = truth::MakeAbLine(a, b, 1e5);
    } else if (type == "waypoints") {
      t.path = truth::Path(ReadWaypoints(r.Child("points")));
    } else if (type == "rectangle") {
      // seed 003: 15 × 15 m from A(−7, −7), clockwise
      t.path = truth::MakeRectangle(
          Point(r, "corner_enu_m", {-7, -7}), r.DoubleIn("width_m", 15, 0.5, 1e5),
          r.DoubleIn("height_m", 15, 0.5, 1e5), r.DoubleIn("side_heading_deg", 0, -360, 360),
          r.Bool("clockwise", true), static_cast<int>(r.Int("laps", 1, 1, 1000)));
    } else if (type == "boustrophedon") {
      t.path = ReadBoustrophedon(r, t.vehicle);
    } else if (type == "circle") {
      t.path =
          truth::MakeCircle(Point(r, "centre_enu_m", {0, 0}), r.DoubleIn("radius_m", 5, 0.2, 1e5),
                            r.DoubleIn("start_bearing_deg", 180, -360, 360),
                            r.Choice("direction", "left", {"left", "right"}) == "left",
                            static_cast<int>(r.Int("laps", 1, 1, 1000)), 180);
    }
  } catch (const std::invalid_argument& e) {
    r.Fail(e.what());
  }
}

void ReadTerrain(const YamlReader& r, truth::TruthConfig& t) {
  const std::string type = r.Choice("type", "flat", {"flat", "plane", "rough"});
  if (type == "flat") r.CheckKeys({"type", "height_m"});
  if (type == "plane") r.CheckKeys({"type", "height_m", "slope_deg", "uphill_heading_deg"});
  if (type == "rough") {
    r.CheckKeys({"type", "height_m", "slope_deg", "uphill_heading_deg", "amplitude_m",
                 "min_wavelength_m", "max_wavelength_m", "waves", "seed"});
  }
  truth::TerrainConfig& c = t.terrain;
  c.type = type == "flat"    ? truth::TerrainConfig::Type::kFlat
           : type == "plane" ? truth::TerrainConfig::Type::kPlane
                             : truth::TerrainConfig::Type::kRough;
  c.height_m = r.DoubleIn("height_m", 0, -1000, 1000);
  c.slope_deg = r.DoubleIn("slope_deg", 0, -45, 45);
  c.uphill_heading_deg = r.DoubleIn("uphill_heading_deg", 0, -360, 360);
  c.amplitude_m = r.DoubleIn("amplitude_m", c.amplitude_m, 0, 2);
  c.min_wavelength_m = r.DoubleIn("min_wavelength_m", c.min_wavelength_m, 0.5, 1000);
  c.max_wavelength_m = r.DoubleIn("max_wavelength_m", c.max_wavelength_m, 0.5, 1000);
  if (c.max_wavelength_m < c.min_wavelength_m)
    r.Fail("max_wavelength_m", "must not be below min_wavelength_m");
  c.waves = static_cast<int>(r.Int("waves", c.waves, 1, 64));
  c.seed = static_cast<std::uint64_t>(r.Int("seed", 1, 0, INT64_MAX));
}

void ReadVibration(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"components"});
  for (const YamlReader& e : r.Child("components").Elements()) {
    e.CheckKeys(
        {"frequency_hz", "heave_accel_mps2", "roll_rate_dps", "pitch_rate_dps", "phase_deg"});
    truth::VibrationComponent v;
    if (!e.Has("frequency_hz")) e.Fail("missing required key 'frequency_hz'");
    v.frequency_hz = e.DoubleIn("frequency_hz", 25, 0.1, 200);
    const double w = 2 * std::numbers::pi * v.frequency_hz;
    // amplitudes are given as what the IMU sees: acceleration and rate
    v.heave_m = e.DoubleIn("heave_accel_mps2", 0, 0, 50) / (w * w);
    v.roll_rad = e.DoubleIn("roll_rate_dps", 0, 0, 200) * kDeg / w;
    v.pitch_rad = e.DoubleIn("pitch_rate_dps", 0, 0, 200) * kDeg / w;
    v.phase_rad = e.DoubleIn("phase_deg", 0, -360, 360) * kDeg;
    t.vibration.components.push_back(v);
  }
}

void ReadTruthOptions(const YamlReader& r, truth::TruthConfig& t) {
  r.CheckKeys({"earth_rotation", "rtol", "atol_m"});
  t.earth_rotation = r.Bool("earth_rotation", t.earth_rotation);
  t.rtol = r.DoubleIn("rtol", t.rtol, 1e-13, 1e-4);
  t.atol_m = r.DoubleIn("atol_m", t.atol_m, 1e-13, 1e-3);
}

}  // namespace

const std::vector<std::string> kTruthSectionKeys{"origin",  "vehicle",   "path",
                                                 "terrain", "vibration", "truth"};

void ReadTruthSections(const YamlReader& root, truth::TruthConfig& t) {
  ReadOrigin(root.Child("origin"), t);
  if (auto v = root.OptionalChild("vehicle")) ReadVehicle(*v, t);
  if (auto p = root.OptionalChild("path")) ReadPath(*p, t);
  if (auto g = root.OptionalChild("terrain")) ReadTerrain(*g, t);
  if (auto v = root.OptionalChild("vibration")) ReadVibration(*v, t);
  if (auto o = root.OptionalChild("truth")) ReadTruthOptions(*o, t);
}

}  // namespace hil::harness

#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/angles.h"

#include "scenario_sections.h"
#include "scenario_truth_keys.h"

namespace hil::harness {
namespace {

// the tables read here (a using-declaration each: the unity build joins the readers' files)
using truth_keys::kOrigin;
using truth_keys::kPath;
using truth_keys::kPathPoint;
using truth_keys::kSpeedStep;
using truth_keys::kSpeedVariation;
using truth_keys::kTerrain;
using truth_keys::kTruthOptions;
using truth_keys::kVehicle;
using truth_keys::kVibration;
using truth_keys::kVibrationComponent;

constexpr double kKmhToMps = 1.0 / 3.6;

void ReadOrigin(const YamlReader& y, truth::TruthConfig& t) {
  const KeyedReader<kOrigin> r(y);
  r.CheckKeys();
  if (!r.Has("lat_deg")) r.Fail("missing required key 'lat_deg'");
  if (!r.Has("lon_deg")) r.Fail("missing required key 'lon_deg'");
  t.origin.lat_deg = r.Number("lat_deg", 0);
  t.origin.lon_deg = r.Number("lon_deg", 0);
  t.origin.height_m = r.Number("height_m", 0);
}

truth::VehicleParams Preset(const std::string& model) {
  if (model == "tractor") return truth::VehicleParams::Tractor();
  if (model == "diff_drive") return truth::VehicleParams::DiffDrive();
  if (model == "skid_steer") return truth::VehicleParams::SkidSteer();
  return truth::VehicleParams::GreenhousePlatform();
}

// The keys of one model family only: a steering key on a yaw-rate model, or the reverse, or a
// skid-steer key on another model.
void RefuseOtherModelsKeys(const KeyedReader<kVehicle>& r, const std::string& model) {
  const bool yaw_rate = model == "diff_drive" || model == "skid_steer";
  if (yaw_rate) {
    for (const char* k : {"wheelbase_m", "max_steer_deg", "max_steer_rate_dps", "steer_lag_s"}) {
      if (r.yaml().Has(k)) r.yaml().Fail(k, "not a parameter of the " + model + " model");
    }
  } else {
    for (const char* k : {"yaw_rate_lag_s", "max_yaw_rate_dps"}) {
      if (r.yaml().Has(k)) r.yaml().Fail(k, "only a parameter of the diff_drive model");
    }
  }
  if (model != "skid_steer") {
    for (const char* k : {"icr_expansion", "icr_offset_m"}) {
      if (r.yaml().Has(k)) r.yaml().Fail(k, "only a parameter of the skid_steer model");
    }
  }
}

void ReadVehicle(const YamlReader& y, truth::TruthConfig& t) {
  const KeyedReader<kVehicle> r(y);
  r.CheckKeys();
  const std::string model = r.Choice("model", "bicycle");
  truth::VehicleParams p = Preset(model);
  RefuseOtherModelsKeys(r, model);
  p.wheelbase_m = r.Number("wheelbase_m", p.wheelbase_m);
  p.track_m = r.Number("track_m", p.track_m);
  p.max_steer_deg = r.Number("max_steer_deg", p.max_steer_deg);
  p.max_steer_rate_dps = r.Number("max_steer_rate_dps", p.max_steer_rate_dps);
  p.steer_lag_s = r.Number("steer_lag_s", p.steer_lag_s);
  p.speed_lag_s = r.Number("speed_lag_s", p.speed_lag_s);
  p.yaw_rate_lag_s = r.Number("yaw_rate_lag_s", p.yaw_rate_lag_s);
  p.max_yaw_rate_dps = r.Number("max_yaw_rate_dps", p.max_yaw_rate_dps);
  p.icr_expansion = r.Number("icr_expansion", p.icr_expansion);
  p.icr_offset_m = r.Number("icr_offset_m", p.icr_offset_m);
  p.slip_gain_rad_per_mps2 = r.Number("slip_gain_rad_per_mps2", p.slip_gain_rad_per_mps2);
  if (auto y_sv = r.OptionalChild("speed_variation")) {
    const KeyedReader<kSpeedVariation> sv(*y_sv);
    sv.CheckKeys();
    p.speed_variation_std = sv.Number("std_percent", 0) / 100.0;
    p.speed_variation_tau_s = sv.Number("correlation_time_s", p.speed_variation_tau_s);
    p.speed_variation_seed = static_cast<std::uint64_t>(sv.Integer("seed", 1));
  }
  t.vehicle = p;
}

template <const auto& T>
Eigen::Vector2d Point(const KeyedReader<T>& r, typename KeyedReader<T>::Key key,
                      Eigen::Vector2d fallback) {
  const auto v = r.Doubles(key, 2, {fallback.x(), fallback.y()});
  for (double x : v) {
    if (!(std::abs(x) <= 1e6)) r.Fail(key, "coordinates must be within 1000 km of the origin");
  }
  return {v[0], v[1]};
}

template <const auto& T>
double Speed(const KeyedReader<T>& r, double fallback) {
  if (r.Has("speed_kmh") && r.Has("speed_mps"))
    r.Fail("speed_mps", "give speed_kmh or speed_mps, not both");
  return r.Has("speed_kmh") ? r.Number("speed_kmh", 0) * kKmhToMps
                            : r.Number("speed_mps", fallback);
}

truth::PathVertex ReadWaypointPair(const YamlReader& w) {
  truth::PathVertex v;
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
  return v;
}

std::vector<truth::PathVertex> ReadWaypoints(const YamlReader& list) {
  std::vector<truth::PathVertex> out;
  for (const YamlReader& y : list.Elements()) {
    if (y.IsSequence()) {
      out.push_back(ReadWaypointPair(y));
      continue;
    }
    const KeyedReader<kPathPoint> w(y);
    truth::PathVertex v;
    w.CheckKeys();
    if (!w.Has("enu_m")) w.Fail("missing required key 'enu_m'");
    v.p_N_m = Point(w, "enu_m", {0, 0});
    if (w.Has("speed_mps") || w.Has("speed_kmh")) v.speed_mps = Speed(w, 0);
    v.stop_s = w.Number("stop_s", 0);
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
  for (const YamlReader& y : prof.Elements()) {
    const KeyedReader<kSpeedStep> step(y);
    step.CheckKeys();
    truth::SpeedStep s;
    s.t_s = step.Number("t_s", 0);
    if (!step.Has("t_s")) step.Fail("missing required key 't_s'");
    if (s.t_s <= last) step.Fail("t_s", "speed profile times must increase");
    last = s.t_s;
    if (!step.Has("speed_mps") && !step.Has("speed_kmh"))
      step.Fail("missing 'speed_mps' or 'speed_kmh'");
    s.speed_mps = Speed(step, 0);
    out.push_back(s);
  }
}

using PathReader = KeyedReader<kPath>;

// A boustrophedon path, its turns no tighter than vehicle `v` can steer.
truth::Path ReadBoustrophedon(const PathReader& r, const truth::VehicleParams& v) {
  truth::BoustrophedonSpec b;
  b.start_p_N_m = Point(r, "row_start_enu_m", {0, 0});
  b.heading_deg = r.Number("row_heading_deg", 0);
  b.row_length_m = r.Number("row_length_m", 100);
  b.row_spacing_m = r.Number("row_spacing_m", 7.5);
  b.rows = static_cast<int>(r.Integer("rows", 4));
  const double r_min =
      v.yaw_rate_commanded() ? 0.0 : v.wheelbase_m / std::tan(v.max_steer_deg * kDeg);
  b.turn_radius_m = r.Number("turn_radius_m", std::max(r_min * 1.05, b.row_spacing_m / 2 * 0.999));
  if (b.turn_radius_m < r_min) {
    r.Fail("turn_radius_m",
           "below the vehicle's minimum turning radius " + std::to_string(r_min) + " m");
  }
  if (b.row_spacing_m < 2 * b.turn_radius_m) {
    r.Fail("row_spacing_m", "row spacing must be at least twice the turn radius (" +
                                std::to_string(b.turn_radius_m) + " m)");
  }
  b.first_turn_right = r.Choice("first_turn", "right") == "right";
  if (r.Has("turn_speed_mps")) b.turn_speed_mps = r.Number("turn_speed_mps", 0);
  return truth::MakeBoustrophedon(b);
}

// The keys a path of `type` takes.
std::vector<PathReader::Key> PathKeys(const std::string& type, bool yaw_rate_model) {
  std::vector<PathReader::Key> keys{"type",          "speed_kmh",   "speed_mps",
                                    "speed_profile", "start_enu_m", "heading_deg"};
  const auto allow = [&keys](std::initializer_list<PathReader::Key> more) {
    keys.insert(keys.end(), more.begin(), more.end());
  };
  if (type == "line") {
    if (yaw_rate_model)
      allow({"yaw_rate_dps"});
    else
      allow({"steer_deg"});
  }
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
  return keys;
}

// The guided path of `type` (not a line).
truth::Path ReadGuidedPath(const PathReader& r, const std::string& type,
                           const truth::VehicleParams& vehicle) {
  if (type == "ab_line") {
    if (!r.Has("a_enu_m") || !r.Has("b_enu_m")) r.Fail("an ab_line needs 'a_enu_m' and 'b_enu_m'");
    const Eigen::Vector2d a = Point(r, "a_enu_m", {0, 0}), b = Point(r, "b_enu_m", {0, 0});
    if ((b - a).norm() < 0.1) r.Fail("b_enu_m", "A and B must be at least 0.1 m apart");
    return truth::MakeAbLine(a, b, 1e5);
  }
  if (type == "waypoints") return truth::Path(ReadWaypoints(r.Child("points")));
  if (type == "rectangle") {
    // seed 003: 15 × 15 m from A(−7, −7), clockwise
    return truth::MakeRectangle(Point(r, "corner_enu_m", {-7, -7}), r.Number("width_m", 15),
                                r.Number("height_m", 15), r.Number("side_heading_deg", 0),
                                r.Bool("clockwise", true), static_cast<int>(r.Integer("laps", 1)));
  }
  if (type == "boustrophedon") return ReadBoustrophedon(r, vehicle);
  return truth::MakeCircle(
      Point(r, "centre_enu_m", {0, 0}), r.Number("radius_m", 5), r.Number("start_bearing_deg", 180),
      r.Choice("direction", "left") == "left", static_cast<int>(r.Integer("laps", 1)), 180);
}

void ReadPath(const YamlReader& y, truth::TruthConfig& t) {
  const PathReader r(y);
  const std::string type = r.Choice("type", "line");
  const bool yaw_rate_model = t.vehicle.yaw_rate_commanded();
  r.CheckKeys(PathKeys(type, yaw_rate_model));

  t.speed_mps = Speed(r, t.speed_mps);
  if (auto prof = r.OptionalChild("speed_profile")) ReadSpeedProfile(*prof, t.speed_profile);
  if (r.Has("start_enu_m")) t.start_p_N_m = Point(r, "start_enu_m", {0, 0});
  if (r.Has("heading_deg")) t.heading_deg = r.Number("heading_deg", 0);
  if (type == "line") {
    if (yaw_rate_model)
      t.yaw_rate_dps =
          r.NumberIn("yaw_rate_dps", 0, -t.vehicle.max_yaw_rate_dps, t.vehicle.max_yaw_rate_dps);
    else
      t.steer_deg = r.NumberIn("steer_deg", 0, -t.vehicle.max_steer_deg, t.vehicle.max_steer_deg);
    return;
  }
  truth::GuidanceConfig& g = t.guidance;
  g.lookahead_m = r.Number("lookahead_m", type == "boustrophedon" ? 3.0 : g.lookahead_m);
  g.rate_hz = r.Number("guidance_rate_hz", g.rate_hz);
  g.stop_decel_mps2 = r.Number("stop_decel_mps2", g.stop_decel_mps2);
  g.turn_in_place_deg = r.Number("turn_in_place_deg", g.turn_in_place_deg);
  try {
    t.path = ReadGuidedPath(r, type, t.vehicle);
  } catch (const std::invalid_argument& e) {
    r.Fail(e.what());
  }
}

void ReadTerrain(const YamlReader& y, truth::TruthConfig& t) {
  const KeyedReader<kTerrain> r(y);
  const std::string type = r.Choice("type", "flat");
  if (type == "flat") r.CheckKeys({"type", "height_m"});
  if (type == "plane") r.CheckKeys({"type", "height_m", "slope_deg", "uphill_heading_deg"});
  if (type == "rough") r.CheckKeys();
  truth::TerrainConfig& c = t.terrain;
  c.type = type == "flat"    ? truth::TerrainConfig::Type::kFlat
           : type == "plane" ? truth::TerrainConfig::Type::kPlane
                             : truth::TerrainConfig::Type::kRough;
  c.height_m = r.Number("height_m", 0);
  c.slope_deg = r.Number("slope_deg", 0);
  c.uphill_heading_deg = r.Number("uphill_heading_deg", 0);
  c.amplitude_m = r.Number("amplitude_m", c.amplitude_m);
  c.min_wavelength_m = r.Number("min_wavelength_m", c.min_wavelength_m);
  c.max_wavelength_m = r.Number("max_wavelength_m", c.max_wavelength_m);
  if (c.max_wavelength_m < c.min_wavelength_m)
    r.Fail("max_wavelength_m", "must not be below min_wavelength_m");
  c.waves = static_cast<int>(r.Integer("waves", c.waves));
  c.seed = static_cast<std::uint64_t>(r.Integer("seed", 1));
}

void ReadVibration(const YamlReader& y, truth::TruthConfig& t) {
  const KeyedReader<kVibration> r(y);
  r.CheckKeys();
  for (const YamlReader& ye : r.Child("components").Elements()) {
    const KeyedReader<kVibrationComponent> e(ye);
    e.CheckKeys();
    truth::VibrationComponent v;
    if (!e.Has("frequency_hz")) e.Fail("missing required key 'frequency_hz'");
    v.frequency_hz = e.Number("frequency_hz", 25);
    const double w = 2 * std::numbers::pi * v.frequency_hz;
    // amplitudes are given as what the IMU sees: acceleration and rate
    v.heave_m = e.Number("heave_accel_mps2", 0) / (w * w);
    v.roll_rad = e.Number("roll_rate_dps", 0) * kDeg / w;
    v.pitch_rad = e.Number("pitch_rate_dps", 0) * kDeg / w;
    v.phase_rad = e.Number("phase_deg", 0) * kDeg;
    t.vibration.components.push_back(v);
  }
}

void ReadTruthOptions(const YamlReader& y, truth::TruthConfig& t) {
  const KeyedReader<kTruthOptions> r(y);
  r.CheckKeys();
  t.earth_rotation = r.Bool("earth_rotation", t.earth_rotation);
  t.rtol = r.Number("rtol", t.rtol);
  t.atol_m = r.Number("atol_m", t.atol_m);
}

}  // namespace

const std::vector<std::string> kTruthSectionKeys{"origin",  "vehicle",   "path",
                                                 "terrain", "vibration", "truth"};

extern const KeySection kOriginSection{"origin", "where the local ENU frame N lies (required)",
                                       kOrigin};
extern const KeySection kVehicleSection{"vehicle", "the truth's vehicle model", kVehicle};
extern const KeySection kSpeedVariationSection{"vehicle.speed_variation",
                                               "variation of the commanded speed", kSpeedVariation};
extern const KeySection kPathSection{
    "path", "the planned path of an open-loop run (closed loop: closed_loop.path_file)", kPath};
extern const KeySection kPathPointSection{"path.points[]", "a waypoint given as a mapping",
                                          kPathPoint};
extern const KeySection kSpeedStepSection{"path.speed_profile[]", "a step of the nominal speed",
                                          kSpeedStep};
extern const KeySection kTerrainSection{"terrain", "the ground", kTerrain};
extern const KeySection kVibrationSection{"vibration", "engine vibration", kVibration};
extern const KeySection kVibrationComponentSection{
    "vibration.components[]", "one sinusoid, given as what the IMU sees", kVibrationComponent};
extern const KeySection kTruthOptionsSection{"truth", "the truth integrator's options",
                                             kTruthOptions};

void ReadTruthSections(const YamlReader& root, truth::TruthConfig& t) {
  ReadOrigin(root.Child("origin"), t);
  if (auto v = root.OptionalChild("vehicle")) ReadVehicle(*v, t);
  if (auto p = root.OptionalChild("path")) ReadPath(*p, t);
  if (auto g = root.OptionalChild("terrain")) ReadTerrain(*g, t);
  if (auto v = root.OptionalChild("vibration")) ReadVibration(*v, t);
  if (auto o = root.OptionalChild("truth")) ReadTruthOptions(*o, t);
}

}  // namespace hil::harness

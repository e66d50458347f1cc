// The GNSS receivers' roughness of the field (issue 41): the sky's obstructions (top-level section
// `obstructions:`), the signal thresholds (`gnss.multipath`) and the rough RTK (`gnss.rtk`).
// Every key with its default and source: gnss_receiver_keys.h (docs/scenario_reference.md); the
// model: vectors/scenarios/README.md, "GNSS as rough as the field".
//
// obstructions:
//   - {kind: tree_line, from_m: [0, 10], to_m: [300, 10], width_m: 6, height_m: 15}
//   - {kind: building, centre_m: [50, -30], size_m: [20, 12], heading_deg: 0, height_m: 8}
//   - {kind: greenhouse}          # the `greenhouse:` section's walls, wall_height_m high
//   each may set loss_db, loss_db_per_m, max_loss_db, reflection_amplitude (kind defaults)
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/world/greenhouse_world.h"

#include "gnss_receiver.h"
#include "gnss_receiver_keys.h"

namespace hil::harness {
namespace {

using gnss_keys::kMultipath;
using gnss_keys::kObstacle;
using gnss_keys::kRtk;
using ObstacleReader = KeyedReader<kObstacle>;

// The kind's figures (see the README for their sources).
world::SkyObstacle KindDefaults(world::SkyObstacleKind kind) {
  world::SkyObstacle o;
  o.kind = kind;
  switch (kind) {
    case world::SkyObstacleKind::kTreeLine:
      o.loss_db_per_m = 0.5, o.max_loss_db = 25, o.reflection_amplitude = 0.2;
      break;
    case world::SkyObstacleKind::kBuilding:
      o.opaque = true, o.reflection_amplitude = 0.5;
      break;
    case world::SkyObstacleKind::kGreenhouse:
      o.loss_db = 3, o.max_loss_db = 25, o.reflection_amplitude = 0.3;
      break;
  }
  return o;
}

// The footprint of the greenhouse section's walls: the rectangle of its four wall segments.
world::OrientedBox GreenhouseFootprint(const world::GreenhouseConfig& c) {
  const world::GreenhouseWorld w(c);
  const Eigen::Vector2d& u = w.row_axis();
  const Eigen::Vector2d& v = w.left_axis();
  double lo_u = 1e300, hi_u = -1e300, lo_v = 1e300, hi_v = -1e300;
  for (const auto& [a, b] : w.walls()) {
    for (const Eigen::Vector2d& p : {a, b}) {
      lo_u = std::min(lo_u, p.dot(u)), hi_u = std::max(hi_u, p.dot(u));
      lo_v = std::min(lo_v, p.dot(v)), hi_v = std::max(hi_v, p.dot(v));
    }
  }
  world::OrientedBox box;
  box.centre_m = 0.5 * (lo_u + hi_u) * u + 0.5 * (lo_v + hi_v) * v;
  box.half_extent_m = Eigen::Vector2d(0.5 * (hi_u - lo_u), 0.5 * (hi_v - lo_v));
  box.heading_rad = std::atan2(u.y(), u.x());
  return box;
}

// The footprint: a segment with a width (from_m, to_m, width_m) or a rectangle (centre_m,
// size_m, heading_deg).
// A point of the footprint the obstacle cannot do without (its absence used to read past an empty
// list).
std::vector<double> RequiredPair(const ObstacleReader& f, ObstacleReader::Key key) {
  if (!f.Has(key))
    f.Fail(key, "required: a footprint is from_m, to_m (and width_m) or centre_m, size_m");
  return f.Doubles(key, 2, {});
}

void ReadFootprint(const ObstacleReader& f, world::SkyObstacle& o) {
  if (f.Has("from_m") || f.Has("to_m")) {
    if (f.Has("centre_m")) f.Fail("centre_m", "give either from_m/to_m or centre_m/size_m");
    const auto a = RequiredPair(f, "from_m");
    const auto b = RequiredPair(f, "to_m");
    const Eigen::Vector2d pa(a[0], a[1]), pb(b[0], b[1]);
    const double len = (pb - pa).norm();
    if (!(len > 0)) f.Fail("to_m", "must differ from from_m");
    o.footprint.centre_m = 0.5 * (pa + pb);
    o.footprint.half_extent_m = Eigen::Vector2d(0.5 * len, 0.5 * f.Number("width_m", 4.0));
    o.footprint.heading_rad = std::atan2(pb.y() - pa.y(), pb.x() - pa.x());
    return;
  }
  const auto c = RequiredPair(f, "centre_m");
  const auto size = RequiredPair(f, "size_m");
  if (!(size[0] > 0) || !(size[1] > 0)) f.Fail("size_m", "length and width must be positive");
  o.footprint.centre_m = Eigen::Vector2d(c[0], c[1]);
  o.footprint.half_extent_m = Eigen::Vector2d(0.5 * size[0], 0.5 * size[1]);
  o.footprint.heading_rad = f.Number("heading_deg", 0) * std::numbers::pi / 180.0;
}

world::SkyObstacle ReadObstacle(const YamlReader& y, const Scenario& s) {
  const ObstacleReader f(y);
  f.CheckKeys();
  if (!f.Has("kind")) f.Fail("kind", "required: tree_line, building or greenhouse");
  const std::string kind = f.Choice("kind", "");
  world::SkyObstacle o = KindDefaults(kind == "tree_line"  ? world::SkyObstacleKind::kTreeLine
                                      : kind == "building" ? world::SkyObstacleKind::kBuilding
                                                           : world::SkyObstacleKind::kGreenhouse);
  const bool from_greenhouse = kind == "greenhouse" && !f.Has("from_m") && !f.Has("centre_m");
  if (from_greenhouse) {
    if (!s.greenhouse)
      f.Fail("kind",
             "a greenhouse without centre_m/size_m takes the greenhouse: section's walls, "
             "and the scenario has none");
    o.footprint = GreenhouseFootprint(*s.greenhouse);
    o.height_m = f.Number("height_m", s.greenhouse->wall_height_m);
  } else {
    ReadFootprint(f, o);
    o.height_m = f.Number("height_m", 0);
    if (!f.Has("height_m")) f.Fail("height_m", "required: the obstacle's height above the ground");
  }
  o.loss_db = f.Number("loss_db", o.loss_db);
  o.loss_db_per_m = f.Number("loss_db_per_m", o.loss_db_per_m);
  o.max_loss_db = f.Number("max_loss_db", o.max_loss_db);
  o.reflection_amplitude = f.Number("reflection_amplitude", o.reflection_amplitude);
  if (o.opaque && (f.Has("loss_db") || f.Has("loss_db_per_m") || f.Has("max_loss_db")))
    f.Fail("loss_db", "a building is opaque: it takes no loss figures");
  return o;
}

}  // namespace

void ReadSkyObstructions(const YamlReader& root, Scenario& s) {
  s.gnss.shading.obstructions.reset();
  const auto list = root.OptionalChild("obstructions");
  if (!list) return;
  if (!list->IsSequence())
    list->Fail("must be a list of {kind: tree_line | building | greenhouse, ...}");
  std::vector<world::SkyObstacle> obstacles;
  for (const YamlReader& item : list->Elements()) obstacles.push_back(ReadObstacle(item, s));
  s.gnss.shading.obstructions = std::make_shared<world::SkyObstructions>(std::move(obstacles));
}

void ReadGnssMultipath(const YamlReader& gnss, Scenario& s) {
  const auto y = gnss.OptionalChild("multipath");
  if (!y) return;
  const KeyedReader<kMultipath> m(*y);
  m.CheckKeys();
  gnss::ShadingConfig& c = s.gnss.shading;
  c.track_min_dbhz = m.Number("track_min_dbhz", c.track_min_dbhz);
  c.nav_min_dbhz = m.Number("nav_min_dbhz", c.nav_min_dbhz);
  if (c.nav_min_dbhz < c.track_min_dbhz)
    m.Fail("nav_min_dbhz", "must not be below track_min_dbhz (a used satellite is tracked)");
  c.correlator_spacing_chip = m.Number("correlator_spacing_chip", c.correlator_spacing_chip);
}

void ReadRtkRoughness(const YamlReader& gnss, Scenario& s) {
  s.gnss.rtk_rough.reset();
  const auto y = gnss.OptionalChild("rtk");
  if (!y) return;
  if (s.gnss.profile != "rtk") y->Fail("only the rtk profile has an RTK solution");
  const KeyedReader<kRtk> r(*y);
  r.CheckKeys();
  gnss::RtkRoughness k;
  k.time_to_fix_s = r.Number("time_to_fix_s", k.time_to_fix_s);
  k.time_to_fix_spread_s = r.Number("time_to_fix_spread_s", k.time_to_fix_spread_s);
  k.refix_s = r.Number("refix_s", k.refix_s);
  k.float_sigma_m = r.Number("float_sigma_m", k.float_sigma_m);
  k.float_converged_sigma_m = r.Number("float_converged_sigma_m", k.float_converged_sigma_m);
  if (k.float_converged_sigma_m > k.float_sigma_m)
    r.Fail("float_converged_sigma_m", "must not exceed float_sigma_m");
  k.float_convergence_s = r.Number("float_convergence_s", k.float_convergence_s);
  k.float_correlation_s = r.Number("float_correlation_s", k.float_correlation_s);
  k.min_sats_fixed = static_cast<int>(r.Integer("min_sats_fixed", k.min_sats_fixed));
  k.fix_min_dbhz = r.Number("fix_min_dbhz", k.fix_min_dbhz);
  k.wrong_fix_probability = r.Number("wrong_fix_probability", k.wrong_fix_probability);
  k.wrong_fix_hold_s = r.Number("wrong_fix_hold_s", k.wrong_fix_hold_s);
  k.wrong_fix_satellites =
      static_cast<int>(r.Integer("wrong_fix_satellites", k.wrong_fix_satellites));
  k.wrong_fix_cycles = static_cast<int>(r.Integer("wrong_fix_cycles", k.wrong_fix_cycles));
  s.gnss.rtk_rough = k;
}

extern const KeySection kGnssSection{"gnss", "the GNSS receivers (firmware_emu/gnss)",
                                     gnss_keys::kGnss};
extern const KeySection kGnssErrorsSection{
    "gnss.errors",
    "the position error model (receiver_model.h): per axis, common + own Gauss–Markov",
    gnss_keys::kErrors};
extern const KeySection kGnssReceiverSection{"gnss.receivers[]", "one receiver of an array",
                                             gnss_keys::kReceiver};
extern const KeySection kGnssFaultSection{"gnss.faults[]", "one fault of the receivers' own",
                                          gnss_keys::kFault};
extern const KeySection kGnssMultipathSection{
    "gnss.multipath", "the receiver's signal thresholds, used only with obstructions", kMultipath};
extern const KeySection kGnssRtkSection{
    "gnss.rtk",
    "profile rtk: the rough RTK solution (rtk_solution.h); a float solution is decimetres, a fixed "
    "one centimetres",
    kRtk};
extern const KeySection kObstacleSection{
    "obstructions[]",
    "one obstacle of the sky over the field as the GNSS antennas see it: a vertical prism on the "
    "ground, given as a segment with a width (from_m, to_m, width_m) or a rectangle (centre_m, "
    "size_m, heading_deg)",
    kObstacle};

}  // namespace hil::harness

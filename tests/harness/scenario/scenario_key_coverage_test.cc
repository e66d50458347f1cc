// One source of truth for the scenario's keys: every top-level section has a table, the readers
// accept exactly their tables' keys (a key accepted but undocumented, or documented but refused,
// fails), and the defaults the tables print are the values the readers use.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness {
namespace {

std::string SourceDir() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return src ? src : ".";
}

const std::string kBase = "name: t\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765}\n";

// A closed loop that loads: the path file is a shipped one.
std::string ClosedLoop(const std::string& channel) {
  const std::string path = SourceDir() + "/vectors/paths/seed003_line_north_15m.path";
  if (channel == "isobus") {
    return "vehicle: {model: tractor}\ncan: {interface: vcan0}\nclosed_loop: {channel: isobus, "
           "path_file: " +
           path + ", controller: c";
  }
  return "vehicle: {model: diff_drive}\nclosed_loop: {path_file: " + path + ", controller: c";
}

// Where each table's section lies in a scenario: documents with `@` standing for "KEY: VALUE"
// inside the section. A key is accepted when one of them takes it.
std::map<std::string, std::vector<std::string>> Contexts() {
  std::map<std::string, std::vector<std::string>> c{
      {"", {"@\n"}},
      {"origin", {"name: t\norigin: {lat_deg: 35, lon_deg: 50, @}\n"}},
      {"vehicle",
       {"vehicle: {@}\n", "vehicle: {model: tractor, @}\n", "vehicle: {model: diff_drive, @}\n",
        "vehicle: {model: skid_steer, @}\n"}},
      {"vehicle.speed_variation", {"vehicle: {speed_variation: {@}}\n"}},
      {"path.points[]", {"path: {type: waypoints, points: [{@}, {enu_m: [9, 9]}]}\n"}},
      {"path.speed_profile[]", {"path: {speed_profile: [{@}]}\n"}},
      {"vibration", {"vibration: {@}\n"}},
      {"vibration.components[]", {"vibration: {components: [{@}]}\n"}},
      {"truth", {"truth: {@}\n"}},
      {"estimator", {"estimator: {@}\n"}},
      {"criteria[]", {"criteria: [{@}]\n"}},
      {"evaluation", {"evaluation: {@}\n"}},
      {"closed_loop", {ClosedLoop("serial_base") + ", @}\n", ClosedLoop("isobus") + ", @}\n"}},
      {"closed_loop.actuator (serial_base)", {ClosedLoop("serial_base") + ", actuator: {@}}\n"}},
      {"closed_loop.actuator (isobus)", {ClosedLoop("isobus") + ", actuator: {@}}\n"}},
      {"closed_loop.pass_to_pass", {ClosedLoop("serial_base") + ", pass_to_pass: {@}}\n"}},
      {"can", {"can: {@}\n"}},
      {"greenhouse", {"greenhouse: {@}\n"}},
      {"greenhouse.ridges", {"greenhouse: {ridges: {@}}\n"}},
      {"greenhouse.posts", {"greenhouse: {posts: {@}}\n"}},
      {"paper[]", {"paper: [{@}]\n"}},
      {"statistical", {"statistical: {@}\n"}},
      {"statistical.criteria[]", {"statistical: {criteria: [{@}]}\n"}},
      {"gnss", {"gnss: {@}\n"}},
      {"gnss.errors", {"gnss: {errors: {@}}\n"}},
      {"gnss.receivers[]", {"gnss: {receivers: [{@}]}\n"}},
      {"gnss.faults[]", {"gnss: {faults: [{@}]}\n"}},
      {"gnss.multipath", {"gnss: {multipath: {@}}\n"}},
      {"gnss.rtk", {"gnss: {profile: rtk, rtk: {@}}\n"}},
      {"obstructions[]", {"obstructions: [{@}]\n"}},
      {"mcu", {"mcu: {@}\n"}},
      {"mcu.magnetic", {"mcu: {magnetic: {@}}\n"}},
      {"mcu.vibration[]", {"mcu: {vibration: [{@}]}\n"}},
      {"mcu.temperature", {"mcu: {temperature: {@}}\n"}},
      {"mcu.can", {"mcu: {can: {@}}\n"}},
      {"mcu.faults[]", {"mcu: {faults: [{@}]}\n"}},
      {"mcu.rough", {"mcu: {rough: {@}}\n"}},
      {"mcu.rough.rpm[]", {"mcu: {rough: {rpm: [{@}]}}\n"}},
      {"mcu.rough.engine_orders[]", {"mcu: {rough: {engine_orders: [{@}]}}\n"}},
      {"mcu.rough.ride[]", {"mcu: {rough: {ride: [{@}]}}\n"}},
      {"mcu.rough.mount", {"mcu: {rough: {mount: {@}}}\n"}},
      {"mcu.rough.temperature_profile[]", {"mcu: {rough: {temperature_profile: [{@}]}}\n"}},
      {"mcu.rough.time_tag", {"mcu: {rough: {time_tag: {@}}}\n"}},
      {"mcu.rough.accel", {"mcu: {rough: {accel: {@}}}\n"}},
      {"mcu.rough.gyro", {"mcu: {rough: {gyro: {@}}}\n"}},
      {"rtk_base", {"rtk_base: {@}\n"}},
      {"rtk_base.position", {"rtk_base: {position: {@}}\n"}},
      {"rtk_base.radio", {"rtk_base: {radio: {@}}\n"}},
      {"rtk_base.radio.outages[]", {"rtk_base: {radio: {outages: [{@}]}}\n"}},
      {"rtk_base.observables", {"rtk_base: {observables: {@}}\n"}},
      {"uwb", {"uwb: {@}\n"}},
      {"uwb.nlos_zones[]", {"uwb: {nlos_zones: [{@}]}\n"}},
      {"wt901c", {"wt901c: {@}\n"}},
      {"lidar", {"greenhouse: {}\nlidar: {@}\n"}},
      {"lidar.reflectivity", {"greenhouse: {}\nlidar: {reflectivity: {@}}\n"}},
      {"rangefinders", {"greenhouse: {}\nrangefinders: {@}\n"}},
      {"rangefinders.units[]", {"greenhouse: {}\nrangefinders: {units: [{@}]}\n"}},
      {"zed_f9p", {"rtk_base: {}\nzed_f9p: {@}\n"}},
      {"zed_f9p.config", {"rtk_base: {}\nzed_f9p: {config: {@}}\n"}},
  };
  for (const char* type : {"line", "ab_line", "waypoints", "rectangle", "boustrophedon", "circle"})
    c["path"].push_back(std::string("path: {type: ") + type + ", @}\n");
  c["path"].push_back("vehicle: {model: diff_drive}\npath: {type: line, @}\n");
  for (const char* type : {"flat", "plane", "rough"})
    c["terrain"].push_back(std::string("terrain: {type: ") + type + ", @}\n");
  return c;
}

// A value of the key's type (in range), as YAML.
std::string SampleValue(const ScenarioKey& k) {
  char buf[64];
  switch (k.type) {
    case KeyType::kNumber:
      std::snprintf(buf, sizeof buf, "%.17g", k.lo);
      return buf;
    case KeyType::kInteger:
      std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(k.lo));
      return buf;
    case KeyType::kBool:
      return "true";
    case KeyType::kString:
      return "x";
    case KeyType::kChoice:
      return std::string(k.choices.front());
    case KeyType::kPoint:
      return "[0, 0]";
    case KeyType::kTime:
      return "\"2026-06-10T08:00:00Z\"";
    case KeyType::kList:
      return "[]";
    case KeyType::kMapping:
      return "{}";
  }
  return "x";
}

std::string Document(const std::string& context, const std::string& key_value) {
  std::string doc = context;
  doc.replace(doc.find('@'), 1, key_value);
  return context.rfind("name: t\n", 0) == 0 ? doc : kBase + doc;
}

// The message of the error loading `text` ("" when it loads).
std::string ErrorOf(const std::string& text) {
  try {
    ParseScenario(text, "t.yaml");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(ScenarioKeyCoverageTest, EveryTopLevelSectionHasATable) {
  EXPECT_EQ(ScenarioReference().find("without a table"), std::string::npos)
      << "a top-level key the loader accepts has no table (scenario_keys.h)";
}

TEST(ScenarioKeyCoverageTest, TheReadersAcceptExactlyTheirTablesKeys) {
  const auto contexts = Contexts();
  for (const KeySection* s : ScenarioKeyTables()) {
    SCOPED_TRACE("section '" + std::string(s->path) + "'");
    const auto c = contexts.find(std::string(s->path));
    ASSERT_NE(c, contexts.end()) << "no context for the section: add one to Contexts()";
    for (const std::string& context : c->second) {
      const std::string error = ErrorOf(Document(context, "zz_undocumented: 1"));
      EXPECT_NE(error.find("zz_undocumented: unknown key"), std::string::npos) << error;
    }
    for (const ScenarioKey& k : s->keys) {
      const std::string refused = std::string(k.name) + ": unknown key";
      bool accepted = false;
      std::string error;
      for (const std::string& context : c->second) {
        error = ErrorOf(Document(context, std::string(k.name) + ": " + SampleValue(k)));
        accepted = accepted || error.find(refused) == std::string::npos;
      }
      EXPECT_TRUE(accepted) << "documented but refused: " << error;
    }
  }
}

// The first figure a row's default names: "0.1" → 0.1, "the profile's (neo-5m 9600, rtk …)" →
// 9600 (the first case's), "226 (0xE2)" → 226; NaN when it names none.
double DefaultFigure(std::string_view text) {
  const std::string t(text);
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str()) return v;
  const std::size_t open = t.find('(');
  if (open == std::string::npos) return std::nan("");
  const char* p = t.c_str() + open + 1;
  double w = std::strtod(p, &end);
  if (end != p) return w;
  const char* space = std::strchr(p, ' ');
  if (space == nullptr) return std::nan("");
  w = std::strtod(space + 1, &end);
  return end != space + 1 ? w : std::nan("");
}

struct DefaultProbe {
  std::string section, key;
  std::string document;  ///< the section present, the key absent
  std::function<double(const Scenario&)> value;
};

std::vector<DefaultProbe> GnssProbes() {
  const std::string fault = "gnss: {faults: [{end_s: 2}]}\n";
  const std::string rtk = "gnss: {profile: rtk, rtk: {}}\n";
  const std::string tree =
      "obstructions: [{kind: tree_line, from_m: [0, 0], to_m: [9, 0], "
      "height_m: 5}]\n";
  auto obstacle = [](const Scenario& s) { return s.gnss.shading.obstructions->obstacles()[0]; };
  return {
      {"gnss", "baud", "gnss: {}\n", [](const Scenario& s) { return s.gnss.baud; }},
      {"gnss", "rate_hz", "gnss: {}\n", [](const Scenario& s) { return s.gnss.rate_hz; }},
      {"gnss", "output_lag_s", "gnss: {}\n", [](const Scenario& s) { return s.gnss.output_lag_s; }},
      {"gnss", "tx_buffer_bytes", "gnss: {}\n",
       [](const Scenario& s) { return static_cast<double>(s.gnss.tx_buffer_bytes); }},
      {"gnss", "count", "gnss: {}\n",
       [](const Scenario& s) { return static_cast<double>(s.gnss.receivers.size()); }},
      {"gnss", "array_radius_m", "gnss: {count: 2}\n",
       [](const Scenario& s) { return s.gnss.receivers[1].p_BA_B_m.norm(); }},
      {"gnss.errors", "horizontal_sigma_m", "gnss: {errors: {}}\n",
       [](const Scenario& s) { return s.gnss.model.horizontal_sigma_m; }},
      {"gnss.errors", "vertical_sigma_m", "gnss: {errors: {}}\n",
       [](const Scenario& s) { return s.gnss.model.vertical_sigma_m; }},
      {"gnss.errors", "correlation_time_s", "gnss: {errors: {}}\n",
       [](const Scenario& s) { return s.gnss.model.correlation_time_s; }},
      {"gnss.errors", "velocity_sigma_mps", "gnss: {errors: {}}\n",
       [](const Scenario& s) { return s.gnss.model.velocity_sigma_mps; }},
      {"gnss.errors", "common_fraction", "gnss: {errors: {}}\n",
       [](const Scenario& s) { return s.gnss.model.common_fraction; }},
      {"gnss.faults[]", "start_s", fault,
       [](const Scenario& s) { return ToSeconds(s.gnss.faults[0].start); }},
      {"gnss.faults[]", "elevation_deg", fault,
       [](const Scenario& s) { return s.gnss.faults[0].elevation_deg; }},
      {"gnss.faults[]", "sigma_m", fault,
       [](const Scenario& s) { return s.gnss.faults[0].sigma_m; }},
      {"gnss.multipath", "track_min_dbhz", "gnss: {multipath: {}}\n",
       [](const Scenario& s) { return s.gnss.shading.track_min_dbhz; }},
      {"gnss.multipath", "nav_min_dbhz", "gnss: {multipath: {}}\n",
       [](const Scenario& s) { return s.gnss.shading.nav_min_dbhz; }},
      {"gnss.multipath", "correlator_spacing_chip", "gnss: {multipath: {}}\n",
       [](const Scenario& s) { return s.gnss.shading.correlator_spacing_chip; }},
      {"gnss.rtk", "time_to_fix_s", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->time_to_fix_s; }},
      {"gnss.rtk", "time_to_fix_spread_s", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->time_to_fix_spread_s; }},
      {"gnss.rtk", "refix_s", rtk, [](const Scenario& s) { return s.gnss.rtk_rough->refix_s; }},
      {"gnss.rtk", "float_sigma_m", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->float_sigma_m; }},
      {"gnss.rtk", "float_converged_sigma_m", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->float_converged_sigma_m; }},
      {"gnss.rtk", "float_convergence_s", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->float_convergence_s; }},
      {"gnss.rtk", "float_correlation_s", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->float_correlation_s; }},
      {"gnss.rtk", "min_sats_fixed", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->min_sats_fixed; }},
      {"gnss.rtk", "fix_min_dbhz", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->fix_min_dbhz; }},
      {"gnss.rtk", "wrong_fix_probability", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->wrong_fix_probability; }},
      {"gnss.rtk", "wrong_fix_hold_s", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->wrong_fix_hold_s; }},
      {"gnss.rtk", "wrong_fix_satellites", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->wrong_fix_satellites; }},
      {"gnss.rtk", "wrong_fix_cycles", rtk,
       [](const Scenario& s) { return s.gnss.rtk_rough->wrong_fix_cycles; }},
      {"obstructions[]", "width_m", tree,
       [=](const Scenario& s) { return 2 * obstacle(s).footprint.half_extent_m.y(); }},
      {"obstructions[]", "heading_deg",
       "obstructions: [{kind: building, centre_m: [0, 0], size_m: [4, 2], height_m: 5}]\n",
       [=](const Scenario& s) { return obstacle(s).footprint.heading_rad; }},
      {"obstructions[]", "loss_db", tree, [=](const Scenario& s) { return obstacle(s).loss_db; }},
      {"obstructions[]", "loss_db_per_m", tree,
       [=](const Scenario& s) { return obstacle(s).loss_db_per_m; }},
      {"obstructions[]", "max_loss_db", tree,
       [=](const Scenario& s) { return obstacle(s).max_loss_db; }},
      {"obstructions[]", "reflection_amplitude", tree,
       [=](const Scenario& s) { return obstacle(s).reflection_amplitude; }},
  };
}

std::vector<DefaultProbe> McuProbes() {
  const std::string mcu = "mcu: {}\n";
  const std::string fault = "mcu: {faults: [{kind: reset}]}\n";
  return {
      {"mcu", "baud", mcu, [](const Scenario& s) { return s.mcu.config.baud; }},
      {"mcu", "imu_rate_hz", mcu, [](const Scenario& s) { return s.mcu.config.imu_rate_hz; }},
      {"mcu", "mag_rate_hz", mcu, [](const Scenario& s) { return s.mcu.config.mag_rate_hz; }},
      {"mcu", "crystal_ppm", mcu, [](const Scenario& s) { return s.mcu.config.crystal_ppm; }},
      {"mcu", "mag_oscillator_ppm", mcu,
       [](const Scenario& s) { return s.mcu.config.mag_oscillator_ppm; }},
      {"mcu", "jitter_us", mcu, [](const Scenario& s) { return s.mcu.config.jitter_us; }},
      {"mcu", "output_latency_s", mcu,
       [](const Scenario& s) { return ToSeconds(s.mcu.config.output_lag); }},
      {"mcu", "reboot_s", mcu, [](const Scenario& s) { return ToSeconds(s.mcu.config.reboot); }},
      {"mcu", "tx_buffer_bytes", mcu,
       [](const Scenario& s) { return static_cast<double>(s.mcu.tx_buffer_bytes); }},
      {"mcu.vibration[]", "frequency_hz", "mcu: {vibration: [{}]}\n",
       [](const Scenario& s) { return s.mcu.config.vibration[0].frequency_hz; }},
      {"mcu.temperature", "start_c", mcu,
       [](const Scenario& s) { return s.mcu.config.temperature_c; }},
      {"mcu.temperature", "rate_c_per_h", mcu,
       [](const Scenario& s) { return s.mcu.config.temperature_rate_c_per_h; }},
      {"mcu.can", "source_address", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.address.source_address; }},
      {"mcu.can", "priority", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.address.priority; }},
      {"mcu.can", "ari_every", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.ari_every; }},
      {"mcu.can", "accs_every", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.accs_every; }},
      {"mcu.can", "ssi2_every", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.ssi2_every; }},
      {"mcu.can", "latency_s", "mcu: {can: {}}\n",
       [](const Scenario& s) { return s.mcu.config.can.latency_s; }},
      {"mcu.faults[]", "start_s", fault,
       [](const Scenario& s) { return ToSeconds(s.mcu.config.faults[0].start); }},
      {"mcu.faults[]", "duration_s", fault,
       [](const Scenario& s) { return ToSeconds(s.mcu.config.faults[0].duration); }},
      {"mcu.faults[]", "probability", fault,
       [](const Scenario& s) { return s.mcu.config.faults[0].probability; }},
      {"mcu.faults[]", "amount", fault,
       [](const Scenario& s) { return s.mcu.config.faults[0].amount; }},
      {"mcu.rough", "internal_rate_hz", "mcu: {rough: {}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.internal_rate_hz; }},
      {"mcu.rough", "accel_aaf_hz", "mcu: {rough: {}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.accel_aaf_hz; }},
      {"mcu.rough", "gyro_aaf_hz", "mcu: {rough: {}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.gyro_aaf_hz; }},
      {"mcu.rough", "ride_reference_speed_mps", "mcu: {rough: {}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.ride_reference_speed_mps; }},
      {"mcu.rough.engine_orders[]", "order",
       "mcu: {rough: {internal_rate_hz: 1000, engine_orders: [{}]}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.engine_orders[0].order; }},
      {"mcu.rough.rpm[]", "t_s", "mcu: {rough: {rpm: [{rpm: 800}]}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.rpm_profile[0].t_s; }},
      {"mcu.rough.temperature_profile[]", "t_s", "mcu: {rough: {temperature_profile: [{c: 20}]}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.temperature_profile[0].t_s; }},
      {"mcu.rough.mount", "frequency_hz", "mcu: {rough: {mount: {}}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.mount.frequency_hz; }},
      {"mcu.rough.mount", "damping_ratio", "mcu: {rough: {mount: {}}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.mount.damping_ratio; }},
      {"mcu.rough.time_tag", "latency_s", "mcu: {rough: {time_tag: {}}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.time_tag.latency_s; }},
      {"mcu.rough.time_tag", "jitter_s", "mcu: {rough: {time_tag: {}}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.time_tag.jitter_s; }},
      {"mcu.rough.time_tag", "imu_clock_ppm", "mcu: {rough: {time_tag: {}}}\n",
       [](const Scenario& s) { return s.mcu.config.rough.time_tag.imu_clock_ppm; }},
  };
}

std::vector<DefaultProbe> RtkBaseAndOtherProbes() {
  const std::string base = "rtk_base: {}\n";
  const std::string ecu = ClosedLoop("isobus") + ", actuator: {}}\n";
  auto c = [](const Scenario& s) { return s.rtk_base.config; };
  auto e = [](const Scenario& s) { return s.closed_loop.isobus.ecu; };
  return {
      {"rtk_base", "station_id", base, [=](const Scenario& s) { return c(s).station_id; }},
      {"rtk_base", "antenna_height_m", base,
       [=](const Scenario& s) { return c(s).antenna_height_m; }},
      {"rtk_base", "msm", base,
       [=](const Scenario& s) { return c(s).msm == rtcm3::MsmKind::kMsm7 ? 7.0 : 4.0; }},
      {"rtk_base", "station_message", base,
       [=](const Scenario& s) { return c(s).station_message; }},
      {"rtk_base", "obs_rate_hz", base, [=](const Scenario& s) { return c(s).obs_rate_hz; }},
      {"rtk_base", "station_interval_s", base,
       [=](const Scenario& s) { return ToSeconds(c(s).station_interval); }},
      {"rtk_base", "output_lag_s", base,
       [=](const Scenario& s) { return ToSeconds(c(s).output_lag); }},
      {"rtk_base", "baud", base, [=](const Scenario& s) { return c(s).baud; }},
      {"rtk_base", "tx_buffer_bytes", base,
       [](const Scenario& s) { return static_cast<double>(s.rtk_base.tx_buffer_bytes); }},
      {"rtk_base.position", "lat_deg", "rtk_base: {position: {}}\n",
       [=](const Scenario& s) { return c(s).lat_deg; }},
      {"rtk_base.position", "lon_deg", "rtk_base: {position: {}}\n",
       [=](const Scenario& s) { return c(s).lon_deg; }},
      {"rtk_base.position", "height_m", "rtk_base: {position: {}}\n",
       [=](const Scenario& s) { return c(s).height_m; }},
      {"rtk_base.radio", "bytes_per_s", base,
       [=](const Scenario& s) { return c(s).radio.bytes_per_s; }},
      {"rtk_base.radio", "latency_s", base,
       [=](const Scenario& s) { return ToSeconds(c(s).radio.latency); }},
      {"rtk_base.radio", "loss_probability", base,
       [=](const Scenario& s) { return c(s).radio.loss_probability; }},
      {"rtk_base.radio.outages[]", "start_s", "rtk_base: {radio: {outages: [{}]}}\n",
       [=](const Scenario& s) { return ToSeconds(c(s).radio.outages[0].start); }},
      {"rtk_base.observables", "elevation_mask_deg", base,
       [=](const Scenario& s) { return c(s).observables.elevation_mask_deg; }},
      {"rtk_base.observables", "zenith_tropo_m", base,
       [=](const Scenario& s) { return c(s).observables.zenith_tropo_m; }},
      {"rtk_base.observables", "vertical_iono_l1_m", base,
       [=](const Scenario& s) { return c(s).observables.vertical_iono_l1_m; }},
      {"rtk_base.observables", "phase_noise_m", base,
       [=](const Scenario& s) { return c(s).observables.phase_noise_m; }},
      {"closed_loop.actuator (isobus)", "deadband_deg", ecu,
       [=](const Scenario& s) { return e(s).deadband_deg; }},
      {"closed_loop.actuator (isobus)", "command_latency_s", ecu,
       [=](const Scenario& s) { return ToSeconds(e(s).command_latency); }},
      {"closed_loop.actuator (isobus)", "watchdog_timeout_s", ecu,
       [=](const Scenario& s) { return ToSeconds(e(s).command_timeout); }},
      {"closed_loop.actuator (isobus)", "status_period_s", ecu,
       [=](const Scenario& s) { return ToSeconds(e(s).status_period); }},
      {"closed_loop.actuator (isobus)", "ecu_address", ecu,
       [=](const Scenario& s) { return e(s).source_address; }},
      {"closed_loop.actuator (isobus)", "guidance_address", ecu,
       [=](const Scenario& s) { return e(s).accepted_sources[0]; }},
      {"closed_loop.actuator (isobus)", "min_engage_speed_mps", ecu,
       [=](const Scenario& s) { return e(s).min_engage_speed_mps; }},
      {"closed_loop.actuator (isobus)", "max_engage_speed_mps", ecu,
       [=](const Scenario& s) { return e(s).max_engage_speed_mps; }},
      {"statistical", "seeds", "statistical: {criteria: [{metric: cep50_m, max: 1}]}\n",
       [](const Scenario& s) { return s.statistical_seeds; }},
  };
}

// The sections whose every figure-valued default is checked against the reader's.
const char* const kProbedSections[] = {"gnss",
                                       "gnss.errors",
                                       "gnss.faults[]",
                                       "gnss.multipath",
                                       "gnss.rtk",
                                       "obstructions[]",
                                       "mcu",
                                       "mcu.vibration[]",
                                       "mcu.temperature",
                                       "mcu.can",
                                       "mcu.faults[]",
                                       "mcu.rough",
                                       "mcu.rough.rpm[]",
                                       "mcu.rough.engine_orders[]",
                                       "mcu.rough.mount",
                                       "mcu.rough.temperature_profile[]",
                                       "mcu.rough.time_tag",
                                       "rtk_base",
                                       "rtk_base.position",
                                       "rtk_base.radio",
                                       "rtk_base.radio.outages[]",
                                       "rtk_base.observables",
                                       "closed_loop.actuator (isobus)",
                                       "statistical"};

TEST(ScenarioKeyCoverageTest, TheTablesDefaultsAreTheReadersOwn) {
  std::vector<DefaultProbe> probes = GnssProbes();
  for (auto&& more : {McuProbes(), RtkBaseAndOtherProbes()})
    probes.insert(probes.end(), more.begin(), more.end());
  std::map<std::pair<std::string, std::string>, const DefaultProbe*> by_key;
  for (const DefaultProbe& p : probes) by_key[{p.section, p.key}] = &p;
  for (const KeySection* s : ScenarioKeyTables()) {
    if (std::find(std::begin(kProbedSections), std::end(kProbedSections), s->path) ==
        std::end(kProbedSections))
      continue;
    for (const ScenarioKey& k : s->keys) {
      const double figure = DefaultFigure(k.default_text);
      if ((k.type != KeyType::kNumber && k.type != KeyType::kInteger) || std::isnan(figure))
        continue;
      SCOPED_TRACE(std::string(s->path) + "." + std::string(k.name) + " (default \"" +
                   std::string(k.default_text) + "\")");
      const auto p = by_key.find({std::string(s->path), std::string(k.name)});
      ASSERT_NE(p, by_key.end()) << "a default with no probe: add one";
      Scenario scenario;
      ASSERT_NO_THROW(scenario = ParseScenario(kBase + p->second->document, "t.yaml"));
      EXPECT_NEAR(p->second->value(scenario), figure, 1e-12 * std::max(1.0, std::abs(figure)));
      EXPECT_GE(figure, k.lo);
      EXPECT_LE(figure, k.hi);
    }
  }
}

}  // namespace
}  // namespace hil::harness

// The device table (harness/src/devices/device_table.cc) is complete and consistent: every
// top-level key of the scenario file belongs to the loader or to exactly one row, every row's
// navd.conf keys are keys navd's own configuration reader takes (and are written by the row for
// some scenario of vectors/scenarios, and the links navd reads are the rows'), and the run's
// devices come from the rows.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/navd_config.h"
#include "hil/harness/devices/device_kind.h"
#include "hil/harness/devices/navd_conf.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/scenario/scenario_reader.h"

namespace hil::harness {
namespace {

std::string ScenarioPath(const std::string& name) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/vectors/scenarios/" + name;
}

TEST(DeviceTableTest, NamesAndSeedStreamsAreUnique) {
  std::set<std::string_view> names;
  std::set<std::uint64_t> streams;
  for (const DeviceKind* k : DeviceKinds()) {
    SCOPED_TRACE(std::string(k->name));
    EXPECT_TRUE(names.insert(k->name).second) << "two rows named " << k->name;
    if (k->seed_stream != 0) {
      EXPECT_TRUE(streams.insert(k->seed_stream).second) << "seed stream shared";
    }
    EXPECT_NE(k->build, nullptr);
    EXPECT_NE(k->links, nullptr);
    EXPECT_FALSE(k->spec.empty());
    EXPECT_FALSE(k->report_section.empty());
    // a row reads its sections, or has none (its spec is inside another section)
    EXPECT_EQ(k->read != nullptr, !k->sections.empty());
    // a row with navd.conf keys writes them, and only such a row has a writer
    EXPECT_EQ(k->write_navd != nullptr, !k->navd_keys.empty());
  }
}

TEST(DeviceTableTest, EveryScenarioKeyBelongsToTheLoaderOrToExactlyOneRow) {
  std::map<std::string, std::vector<std::string>> owners;
  for (const std::string& key : ScenarioOwnKeys()) owners[key].push_back("loader");
  for (const DeviceKind* k : DeviceKinds()) {
    for (std::string_view key : k->sections) owners[std::string(key)].emplace_back(k->name);
  }
  for (const auto& [key, who] : owners) {
    std::string list;
    for (const auto& w : who) list += " " + w;
    EXPECT_EQ(who.size(), 1u) << "key " << key << " read by:" << list;
  }
  // the loader accepts each row's key (a typo of it is refused, naming the key)
  const std::string base = "name: t\norigin: {lat_deg: 35.4796096, lon_deg: 50.5979765}\n";
  for (const DeviceKind* k : DeviceKinds()) {
    for (std::string_view key : k->sections) {
      try {
        ParseScenario(base + std::string(key) + "x: {}\n", "t.yaml");
        ADD_FAILURE() << key << "x was accepted";
      } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("'" + std::string(key) + "'"), std::string::npos)
            << e.what();
      }
    }
  }
}

// A navd.conf key with a receiver's index as N (gnss_device_1 → gnss_device_N).
std::string IndexAsN(std::string key) {
  for (const char* prefix : {"gnss_device_", "antenna_"}) {
    const std::string p = prefix;
    if (key.rfind(p, 0) == 0 && key.size() > p.size() &&
        std::isdigit(static_cast<unsigned char>(key[p.size()]))) {
      std::size_t end = p.size();
      while (end < key.size() && std::isdigit(static_cast<unsigned char>(key[end]))) ++end;
      key = p + "N" + key.substr(end);
    }
  }
  return key;
}

// "section.key" of every line of a navd.conf, receivers' indices as N (gnss_device_1 → _N).
std::set<std::string> NavdKeysIn(const estimator::ConfigFile& f) {
  std::set<std::string> keys;
  for (const estimator::ConfigEntry& e : f.entries())
    keys.insert(e.section + "." + IndexAsN(e.key));
  return keys;
}

// The keys (without their section, indices as N) a row's writer writes for `s`, at every slot.
std::set<std::string> KeysWrittenBy(const DeviceKind& k, const Scenario& s,
                                    const std::string& dir) {
  std::set<std::string> keys;
  if (!k.write_navd) return keys;
  std::ostringstream out;
  for (NavdConfSlot slot : {NavdConfSlot::kInput, NavdConfSlot::kFilter, NavdConfSlot::kSections})
    k.write_navd(slot, s, dir + "/" + s.gnss.link, out);
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) {
    const std::size_t eq = line.find(" = ");
    if (eq != std::string::npos) keys.insert(IndexAsN(line.substr(0, eq)));
  }
  return keys;
}

// The keys of navd.conf that are the estimator section's, not a device's.
bool EstimatorKey(const std::string& key, const Scenario& s) {
  static const std::set<std::string> own = {"input.merge_window_s", "time.leap_seconds",
                                            "filter.mode",          "output.json",
                                            "output.can_interface", "output.nmea_device"};
  if (own.count(key)) return true;
  for (const auto& [k, v] : s.estimator.navd_input) {
    if (key == "input." + k) return true;
  }
  for (const auto& [k, v] : s.estimator.navd_filter) {
    if (key == "filter." + k || key == "odometry." + k) return true;
  }
  return false;
}

// Scenarios of vectors/scenarios that together use every row that writes navd.conf keys: GNSS
// only, the IMU board on serial and on CAN, three receivers, UWB with the WT901C, gyro + wheel
// odometry, the ZED-F9P rover.
const char* const kNavdScenarios[] = {"default.yaml",
                                      "seed000_gps_imu.yaml",
                                      "vcan/can_imu.yaml",
                                      "seed000_three_gps.yaml",
                                      "seed003_rectangle_uwb.yaml",
                                      "seed001_autonomous.yaml",
                                      "rtk_f9p_corrections_cut.yaml"};

TEST(DeviceTableTest, EveryRowsNavdKeysAreReadByNavd) {
  const std::string dir = ::testing::TempDir() + "/device_table_test";
  std::filesystem::create_directories(dir);
  std::set<std::string> written;
  for (const char* name : kNavdScenarios) {
    SCOPED_TRACE(name);
    const Scenario s = LoadScenario(ScenarioPath(name));
    WriteNavdConfig(dir + "/navd.conf", s, dir + "/" + s.gnss.link);
    const estimator::ConfigFile f = estimator::ConfigFile::Load(dir + "/navd.conf");
    // navd's reader refuses an unknown section or key: each one written is one navd reads
    EXPECT_NO_THROW(estimator::NavdConfig::FromFile(f));
    // the links navd reads (the run waits for them and gates them) are links of the row
    for (const DeviceKind* k : DeviceKinds()) {
      if (!k->navd_links) continue;
      const std::vector<std::string> links = k->links(s);
      for (const std::string& link : k->navd_links(s)) {
        EXPECT_NE(std::find(links.begin(), links.end(), link), links.end())
            << k->name << ": navd reads " << link << ", not one of its links";
      }
    }
    // a key may be listed by several rows (gnss_device: the gnss receivers' or the rover's,
    // navd_gnss_source.h), but for each scenario exactly one of them writes it
    for (const std::string& key : NavdKeysIn(f)) {
      if (EstimatorKey(key, s)) continue;
      const std::string bare = key.substr(key.find('.') + 1);
      int rows = 0;
      for (const DeviceKind* k : DeviceKinds()) {
        const bool listed = std::count(k->navd_keys.begin(), k->navd_keys.end(), key) > 0;
        rows += listed && KeysWrittenBy(*k, s, dir).count(bare) ? 1 : 0;
      }
      EXPECT_EQ(rows, 1) << key << " is written, but " << rows << " rows list and write it";
      written.insert(key);
    }
  }
  for (const DeviceKind* k : DeviceKinds()) {
    for (std::string_view key : k->navd_keys) {
      EXPECT_TRUE(written.count(std::string(key)))
          << k->name << " lists " << key << ", which no scenario of the set wrote";
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(DeviceTableTest, TheRunsLinksAreTheRowsLinksInTableOrder) {
  const std::string dir = ::testing::TempDir() + "/device_table_links";
  std::filesystem::create_directories(dir + "/captures");
  for (const char* name : {"seed003_rectangle_uwb.yaml", "seed000_three_gps.yaml"}) {
    SCOPED_TRACE(name);
    const Scenario s = LoadScenario(ScenarioPath(name));
    std::vector<std::string> expected;
    for (const DeviceKind* k : DeviceKinds()) {
      for (const std::string& link : k->links(s)) {
        expected.push_back(link);
        EXPECT_EQ(DeviceKindOfLink(s, link), k);
      }
    }
    const DeviceSet set = BuildDevices(s, 1, dir);
    std::vector<std::string> built;
    for (const auto& [link, path] : set.links) built.push_back(link);
    EXPECT_EQ(built, expected);
    EXPECT_EQ(set.devices.size(), set.endpoints.size());
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

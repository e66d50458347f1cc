// Golden vectors of the receiver under a rough sky (issue 41): the bytes every message type takes
// when a tree line and a building shade the sky (C/N0, used flags, DOPs, prRes, position), and the
// GGA lines of the rough RTK through float, a wrong fix and its hold. The file
// vectors/gnss/neo5m_rough_sky.golden is regenerated here and compared; HIL_REGEN_VECTORS=1
// rewrites it. The values behind the bytes are checked by neo5m_sky_test and rtk_solution_test.
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/neo5m_device.h"

#include "golden_file.h"
#include "hex_bytes.h"

namespace hil::gnss {
namespace {

TruthSample Truth(Time t) {
  TruthSample s;
  s.t = t;
  s.lat_deg = 45.75 + ToSeconds(t) / 111170.0;  // 1 m/s north (m per degree at 45.75°)
  s.lon_deg = 126.63;
  s.height_m = 150.0;
  s.v_NB_N_mps = Eigen::Vector3d(0, 1.0, 0);
  s.p_NB_N_m = Eigen::Vector3d(0, ToSeconds(t), 0);
  return s;
}

std::shared_ptr<const world::SkyObstructions> Sky() {
  world::SkyObstacle trees;
  trees.kind = world::SkyObstacleKind::kTreeLine;
  trees.footprint = {{-9, 90}, {4, 130}, 0};  // 8 m deep, x −13 … −5
  trees.height_m = 18;
  trees.loss_db_per_m = 1.5;
  trees.max_loss_db = 25;
  trees.reflection_amplitude = 0.2;
  world::SkyObstacle barn;
  barn.kind = world::SkyObstacleKind::kBuilding;
  barn.footprint = {{15, 20}, {5, 5}, 0};
  barn.height_m = 12;
  barn.opaque = true;
  barn.reflection_amplitude = 0.5;
  return std::make_shared<world::SkyObstructions>(std::vector<world::SkyObstacle>{trees, barn});
}

std::string Hex(const std::string& bytes) { return hil::test::HexBytes(bytes); }

std::string Describe(const std::vector<SerialMessage>& msgs) {
  std::string o;
  for (const auto& m : msgs) {
    if (m.name.rfind("NMEA", 0) == 0)
      o += m.name + " " + m.bytes.substr(0, m.bytes.size() - 2) + "\n";
    else
      o += m.name + " " + Hex(m.bytes) + "\n";
  }
  return o;
}

std::string Generate() {
  std::string o = "== neo-5m under a tree line and a barn, every message (overload), epoch 3 s\n";
  Neo5mConfig c;
  c.start_utc = ParseIsoUtc("2019-05-14T02:00:00Z");
  c.baud = 115200;
  ReceiverModelConfig m = ProfileByName("neo-5m").model;
  m.p_BA_B_m = Eigen::Vector3d(0, 0, 2.8);
  m.geoid_separation_m = -20.0;
  c.model = m;
  c.shading.obstructions = Sky();
  c.faults.push_back({GnssFault::Kind::kOverload, TimeFromSeconds(0), TimeFromSeconds(1000)});
  Neo5mDevice dev(c, 41);
  std::vector<SerialMessage> last;
  while (dev.next_event_time() <= TimeFromSeconds(3)) {
    DeviceOutput out;
    dev.OnEvent(Truth(dev.next_event_time()), out);
    last = out.serial;
  }
  o += Describe(last);
  o += "== rtk rough: float 2 s, then a wrong fix (probability 1) held; GGA at 0.5 s steps\n";
  Neo5mConfig r;
  r.profile = "rtk";
  r.start_utc = c.start_utc;
  ReceiverModelConfig rm = ProfileByName("rtk").model;
  rm.p_BA_B_m = Eigen::Vector3d(1.2, 0, 2.8);
  rm.geoid_separation_m = -20.0;
  r.model = rm;
  RtkRoughness k;
  k.time_to_fix_s = 2;
  k.wrong_fix_probability = 1.0;
  r.rtk_rough = k;
  Neo5mDevice rtk(r, 42);
  while (rtk.next_event_time() <= TimeFromSeconds(10)) {
    DeviceOutput out;
    const Time t = rtk.next_event_time();
    rtk.OnEvent(Truth(t), out);
    if (std::lround(ToSeconds(t) * 10) % 5 != 0) continue;
    for (const auto& msg : out.serial) {
      if (msg.name == "NMEA-GGA") o += Describe({msg});
    }
  }
  return o;
}

TEST(GnssRoughGoldenTest, VectorsMatchTheEmulator) {
  hil::test::CheckOrWriteGolden("vectors/gnss/neo5m_rough_sky.golden", Generate());
}

}  // namespace
}  // namespace hil::gnss

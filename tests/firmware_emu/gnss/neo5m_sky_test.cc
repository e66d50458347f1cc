// The receiver under an obstructed sky (issue 41): satellites behind a tree line lose C/N0 or
// drop out, DOP and the position error follow, GSV and NAV-SVINFO report the same sky; the rough
// RTK's float/fixed/wrong-fix states reach GGA.
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/neo5m_device.h"
#include "hil/firmware_emu/gnss/nmea_sky_sentences.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss {
namespace {

constexpr double kLat = 45.75, kLon = 126.63;

TruthSample Truth(Time t) {
  TruthSample s;
  s.t = t;
  s.lat_deg = kLat;
  s.lon_deg = kLon;
  s.height_m = 150.0;
  return s;
}

Neo5mConfig Config(const std::string& profile = "neo-5m") {
  Neo5mConfig c;
  c.profile = profile;
  c.start_utc = ParseIsoUtc("2019-05-14T02:00:00Z");
  ReceiverModelConfig m = ProfileByName(profile).model;
  m.p_BA_B_m = Eigen::Vector3d(0, 0, 2);
  c.model = m;
  return c;
}

// A tree line `east_m` east of the antenna (its near face), 6 m deep, `height_m` tall, 400 m long
// north–south: at this place and hour (2019-05-14 02:00 UTC, 45.75 N) three of the eight used
// satellites are east of the antenna at 31–50° (svids 5, 8, 19).
std::shared_ptr<const world::SkyObstructions> TreeLine(double east_m = 8.0, double height_m = 18.0,
                                                       double loss_db_per_m = 4.0) {
  world::SkyObstacle o;
  o.kind = world::SkyObstacleKind::kTreeLine;
  o.footprint = {{east_m + 3, 0}, {3, 200}, 0};
  o.height_m = height_m;
  o.loss_db_per_m = loss_db_per_m;  // 4: a dense hedge, 24 dB and more through its 6 m
  o.max_loss_db = 25;
  o.reflection_amplitude = 0.2;
  return std::make_shared<world::SkyObstructions>(std::vector<world::SkyObstacle>{o});
}

struct Epochs {
  std::vector<NavEpoch> nav;
  std::vector<SerialMessage> out;
};

Epochs RunFor(const Neo5mConfig& c, double end_s, std::uint64_t seed = 3) {
  Neo5mDevice dev(c, seed);
  Epochs r;
  while (dev.next_event_time() <= TimeFromSeconds(end_s)) {
    DeviceOutput out;
    dev.OnEvent(Truth(dev.next_event_time()), out);
    r.nav.push_back(dev.last_epoch());
    r.out.insert(r.out.end(), out.serial.begin(), out.serial.end());
  }
  return r;
}

int Used(const NavEpoch& e) {
  int n = 0;
  for (const auto& s : e.sats) n += s.used ? 1 : 0;
  return n;
}

TEST(Neo5mSkyTest, SatellitesBehindTheTreesLoseSignalAndTheGeometryWorsens) {
  Neo5mConfig open = Config(), shaded = Config();
  shaded.shading.obstructions = TreeLine();
  const Epochs a = RunFor(open, 60), b = RunFor(shaded, 60);
  ASSERT_EQ(a.nav.size(), b.nav.size());
  int fewer = 0, weaker = 0, worse_hdop = 0;
  for (std::size_t k = 0; k < a.nav.size(); ++k) {
    const NavEpoch &ea = a.nav[k], &eb = b.nav[k];
    fewer += Used(eb) < Used(ea) ? 1 : 0;
    worse_hdop += eb.fix.hdop > ea.fix.hdop + 1e-9 ? 1 : 0;
    EXPECT_GE(eb.fix.hdop, ea.fix.hdop - 1e-9) << k;  // never better than the open sky
    for (std::size_t i = 0; i < ea.sats.size(); ++i) {
      const SatelliteView &sa = ea.sats[i], &sb = eb.sats[i];
      ASSERT_EQ(sa.svid, sb.svid);
      // satellites to the east below 55° cross the trees (2 + 9.5·tan 55° = 15.6 m < 18 m)
      const bool east = std::sin(sa.azim_deg * std::numbers::pi / 180) > 0.8;
      if (!sa.sbas && east && sa.elev_deg < 55 && sa.tracked) {
        EXPECT_LT(sb.cno_dbhz, sa.cno_dbhz - 3) << "svid " << sa.svid << " el " << sa.elev_deg;
        ++weaker;
      }
    }
  }
  EXPECT_GT(weaker, 0);
  EXPECT_GT(fewer, 0);
  EXPECT_GT(worse_hdop, 0);
}

TEST(Neo5mSkyTest, MultipathErrorIsTheGeometrysImageOfTheRangeErrorsAndShowsInPrRes) {
  // a tree line that only reflects (no foliage loss): the same satellites stay in use, so the DOPs
  // and the model's own errors are those of the open sky, and the difference between the two
  // fixes is the least-squares image of the satellites' code multipath
  Neo5mConfig open = Config(), shaded = Config();
  shaded.shading.obstructions = TreeLine(8.0, 18.0, 0.0);
  const Epochs a = RunFor(open, 30), b = RunFor(shaded, 30);
  double max_diff_m = 0;
  for (std::size_t k = 1; k < a.nav.size(); ++k) {
    const NavEpoch &ea = a.nav[k], &eb = b.nav[k];
    ASSERT_EQ(Used(ea), Used(eb)) << k;
    ASSERT_DOUBLE_EQ(ea.fix.hdop, eb.fix.hdop) << k;
    std::vector<double> code;
    for (const auto& s : eb.sats) code.push_back(s.code_multipath_m);
    const RangeErrorSolution sol = SolveRangeErrors(eb.sats, code);
    ASSERT_TRUE(sol.valid);
    const double dn_m = (eb.fix.lat_deg - ea.fix.lat_deg) * 111170.0;  // m per degree at 45.75°
    const double de_m =
        (eb.fix.lon_deg - ea.fix.lon_deg) * 111170.0 * std::cos(kLat * std::numbers::pi / 180);
    EXPECT_NEAR(dn_m, sol.dp_N_m.y(), 0.01 + 0.005 * std::abs(sol.dp_N_m.y())) << k;
    EXPECT_NEAR(de_m, sol.dp_N_m.x(), 0.01 + 0.005 * std::abs(sol.dp_N_m.x())) << k;
    EXPECT_NEAR(eb.fix.height_m - ea.fix.height_m, sol.dp_N_m.z(), 1e-6) << k;
    max_diff_m = std::max(max_diff_m, std::hypot(dn_m, de_m));
    // NAV-SVINFO's residuals carry the multipath residuals; hAcc grows by HDOP × their RMS
    for (std::size_t i = 0; i < eb.sats.size(); ++i) {
      if (eb.sats[i].used) {
        EXPECT_NEAR(eb.sats[i].pr_res_m - ea.sats[i].pr_res_m, sol.residual_m[i], 1e-9);
      }
    }
    EXPECT_NEAR(eb.fix.h_acc_m, std::hypot(ea.fix.h_acc_m, sol.sigma_m * eb.fix.hdop), 1e-9);
  }
  // reflections of amplitude 0.2 off a face 8 m away: decimetres to metres
  EXPECT_GT(max_diff_m, 0.1);
}

TEST(Neo5mSkyTest, AFarAwayLowObstacleChangesNoByte) {
  Neo5mConfig open = Config(), far = Config();
  far.shading.obstructions = TreeLine(5000.0, 1.0);  // 1 m tall, 5 km away, below the antenna
  const Epochs a = RunFor(open, 20), b = RunFor(far, 20);
  ASSERT_EQ(a.out.size(), b.out.size());
  for (std::size_t i = 0; i < a.out.size(); ++i) EXPECT_EQ(a.out[i].bytes, b.out[i].bytes) << i;
}

TEST(Neo5mSkyTest, GsvAndSvInfoReportTheShadedSky) {
  Neo5mConfig c = Config();
  c.shading.obstructions = TreeLine();
  const Epochs r = RunFor(c, 10);
  const NavEpoch& e = r.nav.back();
  const auto svinfo = ubx::EncodeNav(ubx::kNavSvInfo, e);
  const std::vector<std::string> gsv = nmea::EncodeGsv(e, 0);
  const int num_ch = svinfo[4];
  for (int ch = 0; ch < num_ch; ++ch) {
    const std::size_t o = 8 + 12 * static_cast<std::size_t>(ch);
    const int svid = svinfo[o + 1];
    const int cno = svinfo[o + 4];
    const bool used = (svinfo[o + 2] & 0x01) != 0;
    for (const auto& s : e.sats) {
      if (s.svid != svid) continue;
      EXPECT_EQ(cno, s.cno_dbhz);
      EXPECT_EQ(used, s.used);
      if (s.tracked && !s.sbas) {
        // "…,PRN,elev,azim,cno" in GSV: the same C/N0
        char field[32];
        std::snprintf(field, sizeof field, "%02d,%02d,%03d,%02d", s.nmea_id(),
                      static_cast<int>(std::lround(s.elev_deg)),
                      static_cast<int>(std::lround(s.azim_deg)) % 360, s.cno_dbhz);
        bool found = false;
        for (const auto& line : gsv) found = found || line.find(field) != std::string::npos;
        EXPECT_TRUE(found) << field;
      }
    }
  }
}

TEST(Neo5mSkyTest, RoughRtkReportsFloatThenFixedAndAWrongFixAsFixed) {
  Neo5mConfig c = Config("rtk");
  RtkRoughness k;
  k.time_to_fix_s = 10;
  k.wrong_fix_probability = 1.0;
  k.wrong_fix_hold_s = 1000;
  c.rtk_rough = k;
  const Epochs r = RunFor(c, 30);
  std::vector<std::string> gga;
  for (const auto& m : r.out) {
    if (m.name == "NMEA-GGA") gga.push_back(m.bytes);
  }
  ASSERT_EQ(gga.size(), 301u);
  EXPECT_NE(gga[50].find(",5,"), std::string::npos) << gga[50];    // float
  EXPECT_NE(gga[200].find(",4,"), std::string::npos) << gga[200];  // "fixed", but wrong
  const GnssFix& f = r.nav.back().fix;
  const double err_n_m = (f.lat_deg - kLat) * 111150.0;
  const double err_e_m = (f.lon_deg - kLon) * 111150.0 * std::cos(kLat * std::numbers::pi / 180);
  EXPECT_GT(std::hypot(err_n_m, err_e_m), 0.03) << "a wrong fix is off by decimetres";
  EXPECT_LT(f.h_acc_m, 0.03) << "and the receiver claims centimetres";
}

}  // namespace
}  // namespace hil::gnss

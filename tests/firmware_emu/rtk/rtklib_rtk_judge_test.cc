// RTKLIB (Debian package rtklib) judges the rover's raw observations: the ZED-F9P's RXM-RAWX
// (its UART1 capture) and the base's RTCM 3 (1005 + MSM7) go through convbin to RINEX 3.04, then
// rnx2rtkp computes a kinematic RTK solution (L1 + L2, continuous ambiguity resolution, ratio
// test 3) with the ephemeris of our constellation as a RINEX navigation file (rinex_gps_nav.h says
// why not RTCM 1019). The rover drives north at 1 m/s, 500 m from the base. RTKLIB must fix
// (Q = 1) and its fixed positions agree with our truth to < 2 cm horizontally (issue 44's
// target); the fix rate, time to first fix and the error's RMS and maximum are recorded.
// Skips when convbin or rnx2rtkp is not installed.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/rtk/zed_f9p_device.h"

#include "process_temp_dir.h"
#include "rinex_gps_nav.h"
#include "rtk_base_fixture.h"

namespace hil::rtk {
namespace {

namespace fs = std::filesystem;
constexpr int kSeconds = 300;
constexpr double kSpeed_mps = 1.0;
constexpr double kRad = 3.141592653589793 / 180.0;

// Metres per degree of latitude and longitude at the base (the ellipsoid's radii there).
struct Radii {
  double north_m_per_deg, east_m_per_deg;
};
Radii RadiiAt(double lat_deg, double h_m) {
  const double s = std::sin(lat_deg * kRad);
  const double w = std::sqrt(1.0 - gnss::kWgs84E2 * s * s);
  return {(gnss::kWgs84A_m * (1.0 - gnss::kWgs84E2) / (w * w * w) + h_m) * kRad,
          (gnss::kWgs84A_m / w + h_m) * std::cos(lat_deg * kRad) * kRad};
}

// The rover's antenna: 300 m east and 400 m north of the base at 0 s, then north at 1 m/s.
TruthSample RoverTruth(const RtkBaseConfig& base, Time t) {
  const Radii r = RadiiAt(base.lat_deg, base.height_m);
  TruthSample s;
  s.t = t;
  s.lat_deg = base.lat_deg + (400.0 + kSpeed_mps * ToSeconds(t - Time{})) / r.north_m_per_deg;
  s.lon_deg = base.lon_deg + 300.0 / r.east_m_per_deg;
  s.height_m = base.height_m;
  s.p_EB_E_m = gnss::EcefFromGeodetic(s.lat_deg, s.lon_deg, s.height_m);
  s.v_NB_N_mps = Eigen::Vector3d(0, kSpeed_mps, 0);
  s.speed_mps = kSpeed_mps;
  // heading north: body forward (x) along ENU north
  s.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(kRad * 90, Eigen::Vector3d::UnitZ()));
  return s;
}

struct Verdict {
  int epochs = 0, fixed = 0;
  double first_fix_s = -1, rms_m = 0, max_m = 0;
};

// rnx2rtkp's solution (llh, GPS week and seconds) against the truth of the same instant.
Verdict Judge(const fs::path& pos, const RtkBaseConfig& base, double start_tow_s) {
  Verdict v;
  const Radii r = RadiiAt(base.lat_deg, base.height_m);
  std::ifstream in(pos);
  double sum_sq = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '%') continue;
    std::istringstream f(line);
    double week = 0, tow = 0, lat = 0, lon = 0, h = 0;
    int q = 0;
    if (!(f >> week >> tow >> lat >> lon >> h >> q)) continue;
    ++v.epochs;
    if (q != 1) continue;
    const double t_s = tow - start_tow_s;
    const TruthSample truth = RoverTruth(base, TimeFromSeconds(t_s));
    const double err_m = std::hypot((lat - truth.lat_deg) * r.north_m_per_deg,
                                    (lon - truth.lon_deg) * r.east_m_per_deg);
    if (v.first_fix_s < 0) v.first_fix_s = t_s;
    ++v.fixed;
    sum_sq += err_m * err_m;
    v.max_m = std::max(v.max_m, err_m);
  }
  if (v.fixed > 0) v.rms_m = std::sqrt(sum_sq / v.fixed);
  return v;
}

void Write(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

int Shell(const std::string& cmd) { return std::system(cmd.c_str()); }

constexpr const char* kRnx2rtkpConf =
    "pos1-posmode       =kinematic\n"
    "pos1-frequency     =l1+l2\n"
    "pos1-soltype       =forward\n"
    "pos1-elmask        =10\n"  // the base sends nothing below its 10° mask
    "pos1-ionoopt       =brdc\n"
    "pos1-tropopt       =saas\n"
    "pos1-sateph        =brdc\n"
    "pos1-navsys        =1\n"
    "pos2-armode        =continuous\n"
    "pos2-arthres       =3\n"
    "out-solformat      =llh\n"
    "out-timesys        =gpst\n"
    "out-timeform       =tow\n"
    "out-height         =ellipsoidal\n"
    "ant2-postype       =rinexhead\n";

TEST(RtklibRtkJudge, FixesTheRoversRawxAgainstTheBaseToCentimetres) {
  if (Shell("command -v convbin >/dev/null 2>&1 && command -v rnx2rtkp >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "convbin/rnx2rtkp are not installed (Debian package rtklib; see ci/setup)";
  const fs::path dir = hil::test::ProcessTempDir("rtklib_rtk_judge");
  RtkBaseConfig base = test::KarajBase(rtcm3::MsmKind::kMsm7);
  base.station_message = 1005;  // the ARP itself (no antenna height to apply)
  base.antenna_height_m = 0;
  ZedF9pConfig rover;
  rover.start_utc = base.start_utc;
  rover.flash = {{gnss::ubx::f9key::kRxmRawxUart1, 1}, {gnss::ubx::f9key::kUart1Baudrate, 460800}};
  ZedF9pDevice dev(rover, 11);
  RtkBaseDevice station(base, 1);
  std::string ubx, rtcm;
  int rawx = 0;
  DeviceOutput out;
  for (int k = 0; k < kSeconds; ++k) {
    const Time t = TimeFromSeconds(k);
    for (const SerialMessage& m : station.EncodeEpoch(t)) rtcm += m.bytes;
    ASSERT_EQ(dev.next_event_time(), t);
    dev.OnEvent(RoverTruth(base, t), out);
    for (const SerialMessage& m : out.serial) {
      ubx += m.bytes;
      rawx += m.name == "UBX-RXM-RAWX" ? 1 : 0;
    }
    out.clear();
  }
  ASSERT_EQ(rawx, kSeconds);
  Write(dir / "rover.ubx", ubx);
  Write(dir / "base.rtcm3", rtcm);
  test::WriteRinexGpsNav((dir / "nav.rnx").string(), gnss::Constellation(1), base.start_utc);
  Write(dir / "rtk.conf", kRnx2rtkpConf);
  const std::string d = dir.string() + "/";
  const std::string log = " >> " + d + "rtklib.log 2>&1";
  ASSERT_EQ(Shell("timeout 60 convbin -r ubx -v 3.04 -od -os -o " + d + "rover.obs " + d +
                  "rover.ubx" + log),
            0);
  ASSERT_EQ(Shell("timeout 60 convbin -r rtcm3 -tr 2026/06/10 08:00:00 -v 3.04 -od -os -o " + d +
                  "base.obs " + d + "base.rtcm3" + log),
            0);
  ASSERT_EQ(Shell("timeout 120 rnx2rtkp -k " + d + "rtk.conf -o " + d + "rtk.pos " + d +
                  "rover.obs " + d + "base.obs " + d + "nav.rnx" + log),
            0);
  const double start_tow_s = gnss::GpsFrom(base.start_utc).tow_s();
  const Verdict v = Judge(dir / "rtk.pos", base, start_tow_s);
  const double fix_rate = v.epochs > 0 ? static_cast<double>(v.fixed) / v.epochs : 0;
  std::cout << "RTKLIB: epochs " << v.epochs << ", fixed " << v.fixed << " (" << 100 * fix_rate
            << " %), first fix at " << v.first_fix_s << " s, horizontal error of the fixed RMS "
            << v.rms_m * 1000 << " mm, max " << v.max_m * 1000 << " mm\n";
  RecordProperty("epochs", v.epochs);
  RecordProperty("fix_rate_percent", std::to_string(100 * fix_rate));
  RecordProperty("time_to_first_fix_s", std::to_string(v.first_fix_s));
  RecordProperty("fixed_horizontal_rms_mm", std::to_string(v.rms_m * 1000));
  RecordProperty("fixed_horizontal_max_mm", std::to_string(v.max_m * 1000));
  EXPECT_EQ(v.epochs, kSeconds) << "an RTK solution each epoch";
  EXPECT_GE(fix_rate, 0.9);
  EXPECT_GE(v.first_fix_s, 0.0);
  EXPECT_LT(v.first_fix_s, 30.0);
  EXPECT_LT(v.max_m, 0.02) << "fixed positions within 2 cm of the truth";
}

}  // namespace
}  // namespace hil::rtk

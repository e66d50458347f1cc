// The ZED-F9P rover through a whole run (vectors/scenarios/rtk_f9p_corrections_cut.yaml): hil run
// puts its UBX and NMEA on ttyF9P; its UART2 takes the rtk_base's radio stream, so every RTCM
// frame the base's link carried (captures/ttyRTCM.cap) is an RXM-RTCM of the rover, in the same
// order (but the last epoch's, which arrives after the run's end); report.json's rtk_rover holds
// the RTK timeline: float ≈ 2 s, fixed 10 s later, float 5 s after the cut (60 s), standalone at
// the 20 s CONSTR_DGNSSTO, float and fixed again after 90 s. The same seed, the same capture.
// navd reads the rover (navd_gnss_source.h): its navd.conf names ttyF9P, not the rig's ttyGPS,
// and the raw-fix baseline is the rover's 5 Hz fixes (the rig's receiver gives 10 Hz).
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hil::test {
namespace {

// The RTCM message numbers of a capture's records (tx or drop), in order: the base's from their
// names (RTCM3-1077), the rover's from its RXM-RTCM (msgType, payload bytes 6–7).
std::vector<int> RtcmTypes(const std::string& capture) {
  std::istringstream in(capture);
  std::vector<int> types;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("tx ", 0) != 0 && line.rfind("drop ", 0) != 0) continue;
    std::istringstream f(line);
    std::string dir, t, period, wall, name, data;
    f >> dir >> t >> period >> wall >> name >> data;
    if (name.rfind("RTCM3-", 0) == 0) types.push_back(std::stoi(name.substr(6)));
    if (name == "UBX-RXM-RTCM" && data.size() >= 28)
      types.push_back(std::stoi(data.substr(26, 2) + data.substr(24, 2), nullptr, 16));
  }
  return types;
}

TEST(RtkF9pE2eTest, RoverFollowsTheRadioCorrections) {
  TempDir dir("rtk_f9p_e2e");
  const std::string scenario = SourceDir() + "/vectors/scenarios/rtk_f9p_corrections_cut.yaml";
  const CommandResult r = RunCommand(BinDir() + "/hil run " + scenario + " --out " + dir / "a");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json report = nlohmann::json::parse(ReadFile(dir / "a/report.json"));
  ASSERT_TRUE(report.contains("rtk_rover")) << "no rtk_rover section";
  const auto& tl = report["rtk_rover"]["timeline"];
  ASSERT_EQ(tl.size(), 7U) << tl.dump();
  const int want_state[] = {0, 1, 2, 1, 0, 1, 2};
  // 5 Hz epochs; the first frames arrive ≈ 0.4 s, so float at the first epoch ≥ 1.4 s
  const double want_t[] = {0.0, 1.6, 11.6, 64.4, 79.4, 91.6, 101.6};
  for (std::size_t k = 0; k < tl.size(); ++k) {
    EXPECT_EQ(tl[k]["carr_soln"].get<int>(), want_state[k]) << k;
    EXPECT_NEAR(tl[k]["t_s"].get<double>(), want_t[k], 0.21) << k;
  }
  EXPECT_EQ(report["rtk_rover"]["rtcm_crc_failed"].get<int>(), 0);

  // the rover received the base link's frames: RXM-RTCM's msgType sequence against ttyRTCM's
  const std::string rover_cap = ReadFile(dir / "a/captures/ttyF9P.cap");
  const std::vector<int> base = RtcmTypes(ReadFile(dir / "a/captures/ttyRTCM.cap"));
  const std::vector<int> rxm = RtcmTypes(rover_cap);
  ASSERT_GE(base.size(), 100U);
  EXPECT_EQ(rxm.size() + 2, base.size());  // the last epoch (1006 + 1077 at 150 s) arrives late
  EXPECT_EQ(rxm, std::vector<int>(base.begin(), base.begin() + static_cast<long>(rxm.size())));
  EXPECT_EQ(static_cast<int>(report["rtk_rover"]["rtcm_frames"].get<int>()),
            static_cast<int>(rxm.size()));
  EXPECT_NE(rover_cap.find("UBX-NAV-PVT"), std::string::npos);
  EXPECT_NE(rover_cap.find("NMEA-GGA"), std::string::npos);

  ASSERT_EQ(RunCommand(BinDir() + "/hil run " + scenario + " --out " + dir / "b").exit_code, 0);
  EXPECT_EQ(ReadFile(dir / "b/captures/ttyF9P.cap"), rover_cap);
}

// The number of data lines of a CSV file (its header left out).
std::size_t CsvRows(const std::string& text) {
  std::size_t lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines > 0 ? lines - 1 : 0;
}

TEST(RtkF9pE2eTest, NavdAndTheRawFixBaselineReadTheRover) {
  TempDir dir("rtk_f9p_navd_e2e");
  const std::string scenario = SourceDir() + "/vectors/scenarios/rtk_f9p_corrections_cut.yaml";
  const CommandResult r =
      RunCommand(BinDir() + "/hil run " + scenario + " --no-html --out " + dir / "a");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string conf = ReadFile(dir / "a/navd.conf");
  EXPECT_NE(conf.find("gnss_device = " + dir / "a/ttyF9P" + "\n"), std::string::npos) << conf;
  EXPECT_NE(conf.find("gnss_baud = 115200\n"), std::string::npos) << conf;
  EXPECT_EQ(conf.find("ttyGPS"), std::string::npos) << conf;
  const nlohmann::json report = nlohmann::json::parse(ReadFile(dir / "a/report.json"));
  // the baseline's fixes are the rover's: one per 5 Hz epoch with a fix over the scored 25-150 s
  // (the rig's receiver would give 10 Hz), and gnss_fixes.csv every one of them from its first
  // fix at 1 s
  EXPECT_EQ(report["baselines"]["samples"].get<std::size_t>(), (150U - 25U) * 5 + 1);
  EXPECT_EQ(CsvRows(ReadFile(dir / "a/gnss_fixes.csv")), (150U - 1U) * 5 + 1);
  // navd's GNSS counters speak for the rover's link
  bool rover_link = false;
  for (const auto& l : report["link_integrity"]) {
    if (l["links"] == nlohmann::json::array({"ttyF9P"})) {
      rover_link = true;
      EXPECT_EQ(l["role"], "gnss");
      EXPECT_TRUE(l["intact"].get<bool>()) << l.dump();
    }
  }
  EXPECT_TRUE(rover_link) << report["link_integrity"].dump();
}

}  // namespace
}  // namespace hil::test

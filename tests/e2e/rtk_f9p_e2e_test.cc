// The ZED-F9P rover through a whole run (vectors/scenarios/rtk_f9p_corrections_cut.yaml): hil run
// puts its UBX and NMEA on ttyF9P; its UART2 takes the rtk_base's radio stream, so every RTCM
// frame the base's link carried (captures/ttyRTCM.cap) is an RXM-RTCM of the rover, in the same
// order (but the last epoch's, which arrives after the run's end); report.json's rtk_rover holds
// the RTK timeline: float ≈ 2 s, fixed 10 s later, float 5 s after the cut (60 s), standalone at
// the 20 s CONSTR_DGNSSTO, float and fixed again after 90 s. The same seed, the same capture.
#include <sstream>
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

}  // namespace
}  // namespace hil::test

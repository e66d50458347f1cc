// Issue 44's RTK scenarios through `hil run`, each checked on its RTK state timeline (report.json
// rtk_rover) and on the rover's bytes (captures/ttyF9P.cap):
//  - dual_antenna_heading: the moving-base rover's baseline state (float ≈ 1.2 s, fixed 10 s
//    later) and its NAV-RELPOSNED heading (300°: the right antenna to the left one across the
//    roof of a tractor heading 30°), isMoving and relPosHeadingValid;
//  - rtk_f9p_base_20km: fixed 30 s after the float (10 s + 1 s/km), hAcc 36 mm (1 ppm);
//  - rtk_f9p_radio_loss: 10 % of the base's packets lost, the rover stays fixed.
// The HTML report plots the timeline (plots/rtk_timeline.svg).
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hil::test {
namespace {

struct CapturedUbx {
  double t_s = 0;
  std::string name;
  std::vector<unsigned char> bytes;  // the whole frame
};

// The capture's records, sent (tx) or dropped for want of a reader (drop): what the device
// produced; emulated time (ns in the capture), name and bytes (hex).
std::vector<CapturedUbx> Records(const std::string& capture) {
  std::istringstream in(capture);
  std::vector<CapturedUbx> out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("tx ", 0) != 0 && line.rfind("drop ", 0) != 0) continue;
    std::istringstream f(line);
    std::string dir, t, period, wall, name, data;
    f >> dir >> t >> period >> wall >> name >> data;
    CapturedUbx r{std::stod(t) * 1e-9, name, {}};
    for (std::size_t k = 0; k + 1 < data.size(); k += 2)
      r.bytes.push_back(static_cast<unsigned char>(std::stoi(data.substr(k, 2), nullptr, 16)));
    out.push_back(std::move(r));
  }
  return out;
}

std::int64_t Le(const std::vector<unsigned char>& b, std::size_t off, std::size_t n, bool sign) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < n; ++k) v |= static_cast<std::uint64_t>(b[6 + off + k]) << (8 * k);
  if (sign && (v >> (8 * n - 1) & 1U) != 0) v |= ~0ULL << (8 * n);
  return static_cast<std::int64_t>(v);
}

struct RunOutputs {
  nlohmann::json report;
  std::vector<CapturedUbx> rover;
  std::string dir;
};

RunOutputs HilRun(const TempDir& tmp, const std::string& name) {
  const std::string out = tmp / name;
  const std::string scenario = SourceDir() + "/vectors/scenarios/" + name + ".yaml";
  const CommandResult r = RunCommand(BinDir() + "/hil run " + scenario + " --out " + out);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const auto report = nlohmann::json::parse(ReadFile(out + "/report.json"));
  std::printf("%s: %.1f s emulated in %.3f s\n", name.c_str(), report["sim_time_s"].get<double>(),
              report["wall_time_s"].get<double>());
  return {report, Records(ReadFile(out + "/captures/ttyF9P.cap")), out};
}

void ExpectTimeline(const nlohmann::json& report, const std::vector<int>& states,
                    const std::vector<double>& times_s) {
  ASSERT_TRUE(report.contains("rtk_rover"));
  const auto& tl = report["rtk_rover"]["timeline"];
  ASSERT_EQ(tl.size(), states.size()) << tl.dump();
  for (std::size_t k = 0; k < tl.size(); ++k) {
    EXPECT_EQ(tl[k]["carr_soln"].get<int>(), states[k]) << k;
    EXPECT_NEAR(tl[k]["t_s"].get<double>(), times_s[k], 0.21) << k;
  }
}

TEST(RtkScenariosE2eTest, DualAntennaHeading) {
  TempDir tmp("rtk_dual_antenna");
  const RunOutputs run = HilRun(tmp, "dual_antenna_heading");
  // the moving base's first frames are in 37 ms after epoch 0: float at 1.2 s, fixed at 11.2 s
  ExpectTimeline(run.report, {0, 1, 2}, {0.0, 1.2, 11.2});
  int fixed = 0;
  for (const CapturedUbx& m : run.rover) {
    if (m.name != "UBX-NAV-RELPOSNED" || m.t_s < 12) continue;
    const auto flags = static_cast<std::uint32_t>(Le(m.bytes, 60, 4, false));
    EXPECT_EQ(flags >> 3 & 3U, 2U) << m.t_s;
    EXPECT_EQ(flags & 0x1E7U, 0x127U) << "fixOK diff relValid moving headingValid; no miss";
    const double heading_deg = static_cast<double>(Le(m.bytes, 24, 4, true)) * 1e-5;
    const double acc_deg = static_cast<double>(Le(m.bytes, 52, 4, false)) * 1e-5;
    EXPECT_NEAR(acc_deg, 0.41, 0.02);
    EXPECT_NEAR(std::remainder(heading_deg - 300.0, 360.0), 0.0, 4 * acc_deg) << m.t_s;
    EXPECT_NEAR(static_cast<double>(Le(m.bytes, 20, 4, true)), 120.0, 5.0) << "relPosLength cm";
    ++fixed;
  }
  EXPECT_EQ(fixed, 5 * 48 + 1) << "5 Hz from 12.0 s to 60.0 s";
  for (const CapturedUbx& m : run.rover) {
    if (m.name == "UBX-NAV-PVT" && m.t_s > 12) {
      EXPECT_EQ(Le(m.bytes, 21, 1, false) >> 6, 0) << "the absolute solution stays standalone";
    }
  }
  const auto& heading = run.report["rtk_rover"]["heading"];
  std::printf("dual_antenna_heading: %s\n", heading.dump().c_str());
  EXPECT_EQ(heading["valid_epochs"].get<int>(), fixed + 4) << "fixed from 11.2 s";
  EXPECT_LT(heading["rms_error_deg"].get<double>(), 2 * 0.41);
  EXPECT_LT(heading["max_error_deg"].get<double>(), 4 * 0.41);
  EXPECT_TRUE(std::filesystem::exists(run.dir + "/plots/rtk_timeline.svg"));
  EXPECT_NE(ReadFile(run.dir + "/report.html").find("fig-rtk-timeline"), std::string::npos);
}

TEST(RtkScenariosE2eTest, BaseTwentyKilometresAway) {
  TempDir tmp("rtk_base_20km");
  const RunOutputs run = HilRun(tmp, "rtk_f9p_base_20km");
  // the first frames ≈ 0.6 s after epoch 0: float at 1.6 s, fixed 10 s + 20 × 1 s later
  ExpectTimeline(run.report, {0, 1, 2}, {0.0, 1.6, 31.6});
  int fixed = 0;
  for (const CapturedUbx& m : run.rover) {
    if (m.name != "UBX-NAV-PVT" || (Le(m.bytes, 21, 1, false) >> 6) != 2) continue;
    // hAcc = √2 × (0.01 m + 20 km × 1 ppm) / 1.1774 = 36 mm (12 mm at 2 km)
    EXPECT_EQ(Le(m.bytes, 40, 4, false), 36) << m.t_s;
    ++fixed;
  }
  EXPECT_GT(fixed, 5 * 55);
}

TEST(RtkScenariosE2eTest, RadioLosingTenPercent) {
  TempDir tmp("rtk_radio_loss");
  const RunOutputs run = HilRun(tmp, "rtk_f9p_radio_loss");
  ExpectTimeline(run.report, {0, 1, 2}, {0.0, 1.6, 11.6});
  int msm = 0;
  for (const CapturedUbx& m : Records(ReadFile(run.dir + "/captures/ttyRTCM.cap")))
    msm += m.name == "RTCM3-1077" ? 1 : 0;
  const int lost = 120 - msm;  // one packet per 1 Hz epoch
  EXPECT_GE(lost, 6);
  EXPECT_LE(lost, 20);
  int max_age_code = 0, rxm_msm = 0;
  for (const CapturedUbx& m : run.rover) {
    if (m.name == "UBX-RXM-RTCM") rxm_msm += Le(m.bytes, 6, 2, false) == 1077 ? 1 : 0;
    if (m.name == "UBX-NAV-PVT" && m.t_s > 12)
      max_age_code =
          std::max<int>(max_age_code, static_cast<int>(Le(m.bytes, 78, 2, false) >> 1 & 0xF));
  }
  std::printf("radio loss: %d of 120 packets lost, max lastCorrectionAge code %d\n", lost,
              max_age_code);
  EXPECT_GE(rxm_msm, msm - 1) << "every delivered MSM reached the rover (the last maybe late)";
  EXPECT_GE(max_age_code, 3) << "a lost packet: corrections 1-2 s old (code 2) or older";
  EXPECT_LE(max_age_code, 4) << "never more than 5 s old: fixed throughout";
}

}  // namespace
}  // namespace hil::test

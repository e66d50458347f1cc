// The RTK base through a whole run (vectors/scenarios/rtk_base_radio.yaml): hil run puts the base's
// RTCM 3 on ttyRTCM behind the lossy radio; the capture's frames are whole and CRC-clean, none
// was delivered inside the 60-90 s outage, about 10 % of the others were lost, and RTKLIB's convbin
// (Debian rtklib; the check skips without it) decodes every whole MSM frame of the capture and
// reads the 1006 station 2 km from the origin as the base sent it. The same seed gives the same
// capture.
#include <cmath>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_station.h"

#include "cli_runner.h"

namespace hil::test {
namespace {

std::string HexToBytes(const std::string& hex) {
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  return out;
}

// The bytes the base's UART sent, in order: tx records (a reader took them) and drop records
// (nobody had the pty open: this run leaves ttyRTCM unread, so all of them).
std::string SentBytes(const std::string& capture) {
  std::istringstream in(capture);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("tx ", 0) != 0 && line.rfind("drop ", 0) != 0) continue;
    std::istringstream f(line);
    std::string dir, t, period, wall, name, data;
    f >> dir >> t >> period >> wall >> name >> data;
    out += HexToBytes(data);
  }
  return out;
}

TEST(RtkBaseE2eTest, RunDeliversTheBaseStreamThatRtklibDecodes) {
  TempDir dir("rtk_base_e2e");
  const std::string scenario = SourceDir() + "/vectors/scenarios/rtk_base_radio.yaml";
  const CommandResult r = RunCommand(BinDir() + "/hil run " + scenario + " --out " + dir / "a");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string capture = ReadFile(dir / "a/captures/ttyRTCM.cap");
  const std::string bytes = SentBytes(capture);
  const rtcm3::SplitResult split = rtcm3::Split(bytes);
  EXPECT_EQ(split.skipped_bytes, 0U);
  int msm = 0;
  std::size_t whole = 0;
  std::optional<rtcm3::StationInfo> station;
  for (const std::string& body : split.bodies) {
    whole += body.size() + 6;
    if (rtcm3::MessageNumber(body) == 1006) station = rtcm3::DecodeStation(body);
    if (rtcm3::MessageNumber(body) != 1077) continue;
    ++msm;
    rtcm3::BitReader br(body);
    br.GetUnsigned(24);
    const double tow_s = static_cast<double>(br.GetUnsigned(30)) * 1e-3;
    // 2026-06-10 08:00:00 UTC is GPS time of week 288018 s (Wednesday, GPS - UTC = 18 s)
    const double t = tow_s - 288018.0;
    // the epoch at the run's end (120 s) is queued and captured as a drop like the others
    EXPECT_TRUE(t >= 0.0 && t <= 120.0) << "an MSM of t = " << t << " s";
    EXPECT_FALSE(t >= 60.0 && t < 90.0) << "an MSM of t = " << t << " s crossed the outage";
  }
  EXPECT_GE(msm, 60);  // 90 epochs outside the outage, 10 % lost
  EXPECT_LE(msm, 88);
  ASSERT_TRUE(station.has_value());
  EXPECT_EQ(station->station_id, 44);
  const Eigen::Vector3d origin = gnss::EcefFromGeodetic(35.4796096, 50.5979765, 1312.0);
  EXPECT_NEAR((station->arp_E_m - origin).norm(), std::sqrt(1200.0 * 1200 + 1600 * 1600 + 9), 1e-3);

  // the same seed, the same capture to the last record (a pty nobody has open drops every byte
  // at once: nothing depends on how much the kernel's buffer holds)
  ASSERT_EQ(RunCommand(BinDir() + "/hil run " + scenario + " --out " + dir / "b").exit_code, 0);
  EXPECT_EQ(ReadFile(dir / "b/captures/ttyRTCM.cap"), capture);

  if (RunCommand("command -v convbin").exit_code != 0) {
    GTEST_SKIP() << "convbin is not installed (Debian package rtklib; see ci/setup)";
  }
  WriteFile(dir / "base.rtcm3",
            bytes.substr(0, whole));  // whole frames only (see the scenario README)
  const CommandResult c = RunCommand("timeout 60 convbin -r rtcm3 -tr 2026/06/10 08:00:00 -o " +
                                     dir / "base.obs" + " " + dir / "base.rtcm3");
  ASSERT_EQ(c.exit_code, 0) << c.out;
  const std::string rinex = ReadFile(dir / "base.obs");
  int epochs = 0;
  std::istringstream in(rinex);
  Eigen::Vector3d approx = Eigen::Vector3d::Zero();
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '>') ++epochs;
    if (line.find("APPROX POSITION XYZ") != std::string::npos)
      std::istringstream(line) >> approx.x() >> approx.y() >> approx.z();
  }
  EXPECT_EQ(epochs, msm) << "RTKLIB decoded " << epochs << " of " << msm << " MSM frames";
  EXPECT_LT((approx - station->arp_E_m).norm(), 0.001);
}

}  // namespace
}  // namespace hil::test

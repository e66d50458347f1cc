// RTKLIB (Debian package rtklib) judges the emulated base's RTCM 3 stream: convbin decodes it to
// RINEX 3.04. Every MSM frame sent is an epoch of the RINEX file (RTKLIB drops frames whose
// CRC-24Q fails: the corrupted-byte case shows the count catches it), each epoch holds our
// satellites, the station position RTKLIB read from 1005/1006 is the surveyed ARP to < 1 mm, the
// antenna height is 1006's, and RTKLIB's pseudoranges, phases, Dopplers and SNRs are the values
// we encoded; the moving base's stream (4072.0 + MSM) decodes the same. Skips when convbin is not
// installed. (convbin's -trace 2 and above crash in Debian's
// 2.4.3 b34, so RTKLIB's own error messages cannot be read; the frame count stands for them.)
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/rtk/moving_base.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_moving_base.h"
#include "hil/firmware_emu/rtk/rtcm3_msm.h"

#include "rtk_base_fixture.h"

namespace hil::rtk {
namespace {

namespace fs = std::filesystem;
constexpr int kSeconds = 120;

struct RinexObs {
  Eigen::Vector3d approx_E_m = Eigen::Vector3d::Zero();
  double delta_h_m = -1;
  std::vector<std::string> types;  // GPS observation types in column order
  // epoch (seconds of the GPS day) → PRN → values by type
  std::map<int, std::map<int, std::map<std::string, double>>> epochs;
};

RinexObs ReadRinex(const fs::path& file) {
  RinexObs r;
  std::ifstream in(file);
  std::string line;
  bool header = true;
  int epoch = -1;
  while (std::getline(in, line)) {
    if (header) {
      const std::string label = line.size() > 60 ? line.substr(60) : "";
      std::istringstream v(line.substr(0, 60));
      if (label.rfind("APPROX POSITION XYZ", 0) == 0)
        v >> r.approx_E_m.x() >> r.approx_E_m.y() >> r.approx_E_m.z();
      if (label.rfind("ANTENNA: DELTA H/E/N", 0) == 0) v >> r.delta_h_m;
      if (label.rfind("SYS / # / OBS TYPES", 0) == 0 && line[0] == 'G') {
        std::string sys, t;
        int n = 0;
        v >> sys >> n;
        while (v >> t) r.types.push_back(t);
      }
      if (label.rfind("END OF HEADER", 0) == 0) header = false;
      continue;
    }
    if (line[0] == '>') {
      std::istringstream v(line.substr(1));
      int y = 0, mo = 0, d = 0, h = 0, mi = 0;
      double s = 0;
      v >> y >> mo >> d >> h >> mi >> s;
      epoch = h * 3600 + mi * 60 + static_cast<int>(std::lround(s));
      r.epochs[epoch];
      continue;
    }
    if (line[0] != 'G' || epoch < 0) continue;
    auto& sat = r.epochs[epoch][std::stoi(line.substr(1, 2))];
    for (std::size_t k = 0; k < r.types.size(); ++k) {
      const std::size_t at = 3 + 16 * k;
      if (line.size() < at + 14) break;
      const std::string f = line.substr(at, 14);
      if (f.find_first_not_of(' ') != std::string::npos) sat[r.types[k]] = std::stod(f);
    }
  }
  return r;
}

// Every MSM epoch `sent` is an epoch of `rnx` with the same satellites and RTKLIB's values are
// those we encoded; returns the cells compared and the worst pseudorange error.
std::pair<std::size_t, double> ExpectOurValues(const RinexObs& rnx,
                                               const std::vector<rtcm3::MsmEpoch>& sent,
                                               rtcm3::MsmKind kind) {
  const std::map<int, std::string> sig = {{2, "1C"}, {10, "2W"}};
  double worst_pr_m = 0;
  std::size_t cells = 0;
  for (const rtcm3::MsmEpoch& e : sent) {
    const int sod = static_cast<int>((e.epoch_time_ms / 1000) % 86400);
    if (!rnx.epochs.contains(sod)) {
      ADD_FAILURE() << "epoch " << sod << " missing";
      continue;
    }
    const auto& got = rnx.epochs.at(sod);
    EXPECT_EQ(got.size(), e.satellites.size()) << "epoch " << sod;
    for (const rtcm3::MsmSatellite& s : e.satellites) {
      if (!got.contains(s.id)) {
        ADD_FAILURE() << "G" << s.id << " at " << sod;
        continue;
      }
      for (const rtcm3::MsmSignal& g : s.signals) {
        const std::string code = sig.at(g.signal_id);
        const double lambda = 299792458.0 / (g.signal_id == 2 ? 1575.42e6 : 1227.60e6);
        const auto& v = got.at(s.id);
        const double pr_err = std::abs(v.at("C" + code) - g.pseudorange_m);
        worst_pr_m = std::max(worst_pr_m, pr_err);
        EXPECT_LT(pr_err, 0.0006) << "C" << code << " G" << s.id;  // RINEX: 1 mm steps
        EXPECT_NEAR(v.at("L" + code), g.phaserange_m / lambda, 0.0006 + 1e-6);
        if (kind == rtcm3::MsmKind::kMsm7) {
          EXPECT_NEAR(v.at("D" + code), -g.phaserange_rate_mps / lambda, 0.001);
          EXPECT_NEAR(v.at("S" + code), g.cnr_dbhz, 0.25);  // RTKLIB keeps SNR in 0.25 dBHz
        } else {
          EXPECT_NEAR(v.at("S" + code), g.cnr_dbhz, 0.001);
        }
        ++cells;
      }
    }
  }
  return {cells, worst_pr_m};
}

class RtklibJudge : public ::testing::TestWithParam<rtcm3::MsmKind> {
 protected:
  void SetUp() override {
    if (std::system("command -v convbin >/dev/null 2>&1") != 0)
      GTEST_SKIP() << "convbin is not installed (Debian package rtklib; see ci/setup)";
    dir_ = fs::temp_directory_path() / ("hil_rtklib_judge_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  // Runs convbin on `stream` and returns the RINEX it wrote.
  RinexObs Convert(const std::string& stream, const std::string& name) {
    const fs::path in = dir_ / (name + ".rtcm3"), out = dir_ / (name + ".obs");
    std::ofstream(in, std::ios::binary) << stream;
    const std::string cmd =
        "timeout 60 convbin -r rtcm3 -tr 2026/06/10 08:00:00 -v 3.04 -od -os -o " + out.string() +
        " " + in.string() + " > " + (dir_ / "convbin.log").string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return ReadRinex(out);
  }
  fs::path dir_;
};

TEST_P(RtklibJudge, DecodesEveryFrameWithOurValuesAndStation) {
  RtkBaseConfig c = test::KarajBase(GetParam());
  c.station_message = GetParam() == rtcm3::MsmKind::kMsm7 ? 1006 : 1005;
  RtkBaseDevice base(c, 1);
  std::string stream;
  std::vector<rtcm3::MsmEpoch> sent;  // what the MSMs carry (decoded by our reader)
  for (int k = 0; k < kSeconds; ++k) {
    for (const SerialMessage& m : base.EncodeEpoch(TimeFromNs(k * 1000000000LL))) stream += m.bytes;
  }
  for (const std::string& body : rtcm3::Split(stream).bodies) {
    rtcm3::MsmKind kind{};
    if (rtcm3::MessageNumber(body) == 1070 + static_cast<int>(GetParam()))
      sent.push_back(rtcm3::DecodeGpsMsm(body, kind));
  }
  ASSERT_EQ(sent.size(), static_cast<std::size_t>(kSeconds));
  const RinexObs rnx = Convert(stream, "base");
  // every MSM frame is an epoch of RTKLIB's RINEX
  EXPECT_EQ(rnx.epochs.size(), sent.size());
  // the station: 1005/1006 ARP against the surveyed base (RINEX prints 0.1 mm)
  const double arp_error_m = (rnx.approx_E_m - base.station().arp_E_m).norm();
  EXPECT_LT(arp_error_m, 0.001) << "RTKLIB's station position is " << arp_error_m << " m off";
  EXPECT_NEAR(rnx.delta_h_m, c.station_message == 1006 ? 1.5 : 0.0, 1e-4);
  RecordProperty("arp_error_mm", std::to_string(arp_error_m * 1000));
  const auto [cells, worst_pr_m] = ExpectOurValues(rnx, sent, GetParam());
  RecordProperty("cells_compared", std::to_string(cells));
  RecordProperty("worst_pseudorange_error_mm", std::to_string(worst_pr_m * 1000));
}

TEST_P(RtklibJudge, AFrameWithABadCrcIsNotDecoded) {
  RtkBaseConfig c = test::KarajBase(GetParam());
  std::string stream = test::BaseStream(c, 30, 1);
  // flip one bit inside the 5th frame's body (an MSM: frames 0 and 1 are 1006 and MSM)
  std::size_t at = 0;
  for (int f = 0; f < 4; ++f)
    at += 6 + ((static_cast<unsigned char>(stream[at + 1]) & 3U) << 8) +
          static_cast<unsigned char>(stream[at + 2]);
  stream[at + 20] = static_cast<char>(stream[at + 20] ^ 0x10);
  EXPECT_EQ(rtcm3::Split(stream).crc_errors, 1U);
  EXPECT_EQ(Convert(stream, "corrupted").epochs.size(), 29U);
}

TEST_P(RtklibJudge, DecodesTheMovingBaseStream) {
  // the moving base on a vehicle driving north at 3 m/s: 4072.0 (ours, proprietary to RTKLIB)
  // before each MSM; RTKLIB skips the 4072 frames and decodes every MSM with our values
  MovingBaseConfig c;
  c.msm = GetParam();
  c.p_BA_B_m = Eigen::Vector3d(1.2, -0.6, 2.8);
  MovingBase mb(c, gnss::ParseIsoUtc("2026-06-10T08:00:00Z"), 5);
  std::string stream;
  for (int k = 0; k < kSeconds; ++k) {
    TruthSample t;
    t.t = TimeFromNs(k * 1000000000LL);
    t.lat_deg = 35.4796096 + 3.0 * k / 111000.0;
    t.lon_deg = 50.5979765;
    t.height_m = 1312.0;
    for (const SerialMessage& m : mb.Epoch(t)) stream += m.bytes;
  }
  std::vector<rtcm3::MsmEpoch> sent;
  int pvt = 0;
  for (const std::string& body : rtcm3::Split(stream).bodies) {
    rtcm3::MsmKind kind{};
    if (rtcm3::MessageNumber(body) == 1070 + static_cast<int>(GetParam()))
      sent.push_back(rtcm3::DecodeGpsMsm(body, kind));
    pvt += rtcm3::MessageNumber(body) == rtcm3::kMovingBaseMessage ? 1 : 0;
  }
  ASSERT_EQ(sent.size(), static_cast<std::size_t>(kSeconds));
  EXPECT_EQ(pvt, kSeconds);
  const RinexObs rnx = Convert(stream, "moving_base");
  EXPECT_EQ(rnx.epochs.size(), sent.size());
  const auto [cells, worst_pr_m] = ExpectOurValues(rnx, sent, GetParam());
  EXPECT_GT(cells, 1000U);
  RecordProperty("moving_base_worst_pseudorange_error_mm", std::to_string(worst_pr_m * 1000));
}

std::string KindName(const ::testing::TestParamInfo<rtcm3::MsmKind>& p) {
  return p.param == rtcm3::MsmKind::kMsm4 ? "Msm4" : "Msm7";
}

INSTANTIATE_TEST_SUITE_P(Msm, RtklibJudge,
                         ::testing::Values(rtcm3::MsmKind::kMsm4, rtcm3::MsmKind::kMsm7), KindName);

}  // namespace
}  // namespace hil::rtk

// Round trips through the standard formats: a short run exported (hil export) and navd --kfgins on
// the export against navd's online estimate of the same run; the run's captures replayed into navd
// (navd --replay) against the same; a real u-blox log replayed with its consistency report.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "shared_vectors.h"

namespace hil::test {
namespace {

constexpr double kGpsEpochUnix_s = 315964800.0;
// export → navd --kfgins against navd online: the same filter on the same samples, but not the
// same solutions: navd online reports its output predictor (the filter runs fusion_horizon_s, and
// up to gnss_max_latency_s while it waits for a fix still on the 9600-baud line, behind the newest
// IMU sample, and the predictor carries it forward without the non-holonomic and speed-model
// updates), offline the files are complete and each line is the filter's own state. Also the
// export interpolates the MCU tick between time pulses (online: extrapolated from the last), and
// KF-GINS's format has no HDOP (which scales navd's correlated GNSS error model). Measured on the
// default scenario: mean 2.4 cm, max 14.4 cm (the replay of the captures, below, is exact).
constexpr double kExportMaxTolerance_m = 0.25, kExportMeanTolerance_m = 0.04;

struct Fix {
  double lat, lon, h;
};

// navd's online solutions by GPS seconds of week (rounded to the ms)
std::map<long, Fix> OnlineSolutions(const std::string& jsonl, int leap_s) {
  std::map<long, Fix> out;
  std::ifstream in(jsonl);
  for (std::string line; std::getline(in, line);) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.contains("tov_unix_ns")) continue;
    const double gps_s = j["tov_unix_ns"].get<double>() * 1e-9 - kGpsEpochUnix_s + leap_s;
    out[std::lround(std::fmod(gps_s, 604800.0) * 1000)] = {
        j["lat_deg"].get<double>(), j["lon_deg"].get<double>(), j["height_m"].get<double>()};
  }
  return out;
}

// horizontal differences (m) of a .nav's epochs against the online solutions at the same ms
std::vector<double> Differences(const std::string& nav, const std::map<long, Fix>& online,
                                double from_sow) {
  std::vector<double> d;
  std::ifstream in(nav);
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    double week, sow, lat, lon, h;
    if (!(s >> week >> sow >> lat >> lon >> h) || sow < from_sow) continue;
    const auto it = online.find(std::lround(sow * 1000));
    if (it == online.end()) continue;
    const double dn = (lat - it->second.lat) * 111000.0;
    const double de = (lon - it->second.lon) * 111000.0 * std::cos(lat * M_PI / 180);
    d.push_back(std::hypot(dn, de));
  }
  return d;
}

double Max(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, x);
  return m;
}

class KfginsRoundTrip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("kfgins_rt");
    // the filter of both sides the same: online navd would learn the NMEA velocity's σ from the
    // fixes' velocities, which KF-GINS's GNSS file does not carry, and floor the 10 Hz Razor's
    // accelerometer noise at its scatter (estimator.md, "GNSS velocity noise"); both off here, as
    // they are a difference of inputs, not of the filter this test compares (with them: mean 4.3
    // cm)
    const CommandResult r =
        RunCommand(BinDir() + "/hil run " + SourceDir() + "/vectors/scenarios/default.yaml" +
                   " --set estimator.navd_filter.gnss_velocity_noise=false" +
                   " --set estimator.navd_filter.accel_scatter_tau_s=0 --out " + *dir_ / "run");
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  static void TearDownTestSuite() { delete dir_; }
  static TempDir* dir_;
};
TempDir* KfginsRoundTrip::dir_ = nullptr;

TEST_F(KfginsRoundTrip, ExportThenNavdKfginsMatchesTheOnlineEstimate) {
  const std::string run = *dir_ / "run", exp = *dir_ / "export";
  CommandResult r = RunCommand(BinDir() + "/hil export " + run + " --format kfgins " + exp);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  // the run's own filter settings, aligning itself as it did online
  r = RunCommand(BinDir() + "/navd --kfgins " + exp + "/kf-gins-posvel.yaml --navd-conf " + run +
                 "/navd.conf --align");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto online = OnlineSolutions(run + "/estimate.jsonl", 18);
  ASSERT_GT(online.size(), 500u);
  const std::vector<double> d = Differences(exp + "/result/KF_GINS_Navresult.nav", online,
                                            static_cast<double>(online.begin()->first) * 1e-3);
  ASSERT_GT(d.size(), 500u);
  RecordProperty("max_difference_m", std::to_string(Max(d)));
  EXPECT_LT(Max(d), kExportMaxTolerance_m);
  double sum = 0;
  for (double x : d) sum += x;
  EXPECT_LT(sum / static_cast<double>(d.size()), kExportMeanTolerance_m);
}

TEST_F(KfginsRoundTrip, ReplayOfTheCapturesReproducesTheOnlineEstimate) {
  const std::string run = *dir_ / "run", out = *dir_ / "replay";
  const CommandResult r =
      RunCommand(BinDir() + "/navd --replay " + run + "/captures/ttyGPS.cap " + run +
                 "/captures/ttyIMU.cap --navd-conf " + run + "/navd.conf --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("GNSS fixes: 1"), std::string::npos) << r.out;
  const auto online = OnlineSolutions(run + "/estimate.jsonl", 18);
  const std::vector<double> d = Differences(out + "/KF_GINS_Navresult.nav", online,
                                            static_cast<double>(online.begin()->first) * 1e-3);
  ASSERT_GT(d.size(), 500u);
  RecordProperty("max_difference_m", std::to_string(Max(d)));
  EXPECT_LT(Max(d), 0.01);
}

// a number after `key` in hil dataset score's output
double ScoreField(const std::string& out, const std::string& key) {
  const auto at = out.find(key);
  return at == std::string::npos ? NAN : std::stod(out.substr(at + key.size()));
}

// --nhc-std-mps adds navd's ground-vehicle constraint to the KF-GINS parameters: on our
// generator's vehicle (which never slides sideways) it narrows the vertical error and the drift in
// a 10 s outage (measured on this 200 s set: vertical RMSE 3.5 → 0.5 cm, outage 33.2 → 30.8 cm).
TEST(KfginsNhc, NonHolonomicConstraintNarrowsTheErrors) {
  TempDir dir("kfgins_nhc");
  const std::string d = dir.str();
  ASSERT_EQ(RunCommand(BinDir() + "/hil dataset kfgins " + d +
                       " --seconds 200 --gnss-hz 10 --outage-at 150 --seed 4")
                .exit_code,
            0);
  const std::string score = BinDir() + "/hil dataset score " + d + "/truth.nav " + d +
                            "/result/KF_GINS_Navresult.nav --from-s 100 --outage-at 150";
  ASSERT_EQ(RunCommand(BinDir() + "/navd --kfgins " + d + "/kf-gins.yaml").exit_code, 0);
  const CommandResult plain = RunCommand(score);
  ASSERT_EQ(plain.exit_code, 0) << plain.out;
  const CommandResult r =
      RunCommand(BinDir() + "/navd --kfgins " + d + "/kf-gins.yaml --nhc-std-mps 0.02");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const CommandResult nhc = RunCommand(score);
  ASSERT_EQ(nhc.exit_code, 0) << nhc.out;
  EXPECT_LT(ScoreField(nhc.out, "vertical RMSE "), 0.5 * ScoreField(plain.out, "vertical RMSE "))
      << plain.out << nhc.out;
  EXPECT_LT(ScoreField(nhc.out, "worst outage "), ScoreField(plain.out, "worst outage "))
      << plain.out << nhc.out;
  EXPECT_EQ(
      RunCommand(BinDir() + "/navd --kfgins " + d + "/kf-gins.yaml --nhc-std-mps -1").exit_code, 2);
  // the mounting yaw estimated with the NHC (a car's roof mount): the generator's IMU is mounted
  // straight, so the yaw stays near 0 and the constraint keeps narrowing the vertical error
  const CommandResult yaw = RunCommand(BinDir() + "/navd --kfgins " + d +
                                       "/kf-gins.yaml --nhc-std-mps 0.02 --mount-yaw-std-deg 5");
  ASSERT_EQ(yaw.exit_code, 0) << yaw.out;
  const CommandResult with_yaw = RunCommand(score);
  ASSERT_EQ(with_yaw.exit_code, 0) << with_yaw.out;
  EXPECT_LT(ScoreField(with_yaw.out, "vertical RMSE "),
            0.5 * ScoreField(plain.out, "vertical RMSE "))
      << with_yaw.out;
  EXPECT_EQ(RunCommand(BinDir() + "/navd --kfgins " + d + "/kf-gins.yaml --mount-yaw-std-deg x")
                .exit_code,
            2);
}

TEST(KfginsReplay, RealUbloxLogGivesAConsistencyReport) {
  HIL_SKIP_WITHOUT_GPSD_VECTORS();
  const std::string log = GpsdVector("ublox-lea-5h.log");
  TempDir dir("kfgins_ublox");
  const CommandResult r = RunCommand(BinDir() + "/navd --replay " + log + " --out " + dir.str());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("mode gnss_only"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GNSS fixes: "), std::string::npos) << r.out;
  EXPECT_EQ(RunCommand(BinDir() + "/navd --replay /nonexistent.log --out " + dir.str()).exit_code,
            2);
}

}  // namespace
}  // namespace hil::test

// The generator's files read back by navd's own readers (an independent implementation of the same
// formats), navd run on them, and the run scored: each direction of the KF-GINS formats.
#include "hil/harness/datasets/kfgins_dataset.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/estimator/datasets/kfgins_files.h"
#include "hil/estimator/datasets/kfgins_runner.h"
#include "hil/harness/datasets/kfgins_score.h"

namespace hil::harness {
namespace {

// a temporary folder removed with its files at the end of the scope
struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/kfgins_dataset_XXXXXX";
    path = mkdtemp(tmpl);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

KfginsDatasetOptions ShortSet() {
  KfginsDatasetOptions o;
  o.duration_s = 40;
  o.gnss_rate_hz = 10;
  o.outage_start_s = {25};
  o.seed = 7;
  return o;
}

TEST(KfginsDataset, SameSeedSameBytesAndNavdReadsEveryLine) {
  const TempDir ta, tb;
  const std::string &a = ta.path, &b = tb.path;
  const KfginsDatasetResult r = WriteKfginsDataset(ShortSet(), a);
  WriteKfginsDataset(ShortSet(), b);
  EXPECT_EQ(r.imu_lines, 8000u);
  EXPECT_EQ(r.gnss_lines, 400u - 100u);  // 10 Hz, minus the 10 s outage
  for (const char* f : {"IMU.txt", "GNSS.txt", "truth.nav"})
    EXPECT_EQ(ReadAll(a + "/" + f), ReadAll(b + "/" + f)) << f;
  estimator::datasets::KfginsImuReader imu(a + "/IMU.txt", 7);
  estimator::datasets::KfginsImuRecord rec;
  std::uint64_t n = 0;
  while (imu.Next(rec)) ++n;
  EXPECT_EQ(n, r.imu_lines);
  EXPECT_NEAR(rec.sow, 456340.0, 1e-9);
  // at rest or level driving the accelerometer's down axis (FRD z) reads about −g per interval
  EXPECT_NEAR(rec.dvel_frd_mps.z(), -9.79 * 0.005, 0.002);
}

TEST(KfginsDataset, NavdOnTheGeneratedSetFollowsTheTruth) {
  const TempDir tmp;
  const std::string& dir = tmp.path;
  WriteKfginsDataset(ShortSet(), dir);
  const auto cfg = estimator::datasets::LoadKfginsConfig(dir + "/kf-gins.yaml");
  const auto run =
      estimator::datasets::RunKfgins(cfg, estimator::datasets::NavigatorParamsFromKfgins(cfg));
  EXPECT_EQ(run.imu_epochs, 8000u);
  EXPECT_EQ(run.gnss_rejected, 0u);
  const KfginsScore s =
      ScoreKfginsNav(ReadKfginsNav(dir + "/truth.nav"),
                     ReadKfginsNav(dir + "/result/KF_GINS_Navresult.nav"), 5, {25}, 10);
  EXPECT_EQ(s.epochs, 7001u);   // 5 s … 40 s at 200 Hz, both ends
  EXPECT_LT(s.rmse_h_m, 0.10);  // the 10 s outage's drift included (7.4 cm measured)
  EXPECT_LT(s.outage_max_h_m[0], 0.5);
  EXPECT_GT(s.outage_max_h_m[0], 0.0);
}

TEST(KfginsScore, ErrorsInMetresAndOutageWindows) {
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const KfginsNavLine t0{100.0, 30.0, 114.0, 10.0, zero, zero};
  const KfginsNavLine t1{101.0, 30.0, 114.0, 10.0, zero, zero};
  KfginsNavLine e0 = t0, e1 = t1;
  e1.lat_deg += 1.0 / 110852.0;  // about a metre north at 30°
  const KfginsScore s = ScoreKfginsNav({t0, t1}, {e0, e1}, 0, {0.5}, 1.0);
  EXPECT_EQ(s.epochs, 2u);
  EXPECT_NEAR(s.max_h_m, 1.0, 0.01);
  EXPECT_NEAR(s.rmse_h_m, std::sqrt(0.5), 0.01);
  EXPECT_NEAR(s.outage_max_h_m[0], 1.0, 0.01);
  EXPECT_THROW(ScoreKfginsNav({}, {e0}, 0, {}, 10), std::runtime_error);
}

}  // namespace
}  // namespace hil::harness

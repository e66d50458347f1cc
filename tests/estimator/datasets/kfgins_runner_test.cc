#include "hil/estimator/datasets/kfgins_runner.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/geodesy.h"

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

constexpr double kLat = 30.5, kLon = 114.3, kH = 20.0;

// 20 s at rest, level, facing north: the IMU measures −g on its down axis and the Earth rate;
// 1 Hz fixes of an antenna 0.5 m above the IMU. `yaw_rate_radps`: turning in place about the down
// axis at that rate as well (the z gyro reads it; the antenna, above the IMU, stays put)
std::string WriteStationaryDataset(const std::string& dir, const std::string& extra_yaml = "",
                                   double yaw_rate_radps = 0.0) {
  const double g = NormalGravity(kLat, kH), w = kEarthRate_radps,
               lat = kLat * std::numbers::pi / 180;
  std::string imu, gnss;
  char line[256];
  for (int k = 1; k <= 4000; ++k) {
    const double dt = 0.005;
    std::snprintf(line, sizeof line, "%.3f %.12e 0 %.12e 0 0 %.12e\n", 1000 + k * dt,
                  w * std::cos(lat) * dt, (yaw_rate_radps - w * std::sin(lat)) * dt, -g * dt);
    imu += line;
  }
  LocalTangentFrame f({kLat, kLon, kH});
  const Lla ant = f.ToLla(Eigen::Vector3d(0, 0, 0.5));
  for (int k = 1; k <= 20; ++k) {
    std::snprintf(line, sizeof line, "%d %.11f %.11f %.4f 0.01 0.01 0.02\n", 1000 + k, ant.lat_deg,
                  ant.lon_deg, ant.height_m);
    gnss += line;
  }
  testing::WriteFile(dir, "IMU.txt", imu);
  testing::WriteFile(dir, "GNSS.txt", gnss);
  std::snprintf(line, sizeof line, "initpos: [%.10f, %.10f, %.4f]\n", kLat, kLon, kH);
  const std::string yaml = "imupath: \"" + dir + "/IMU.txt\"\ngnsspath: \"" + dir +
                           "/GNSS.txt\"\noutputpath: \"" + dir +
                           "/out\"\nimudatarate: 200\n"
                           "starttime: 1000.005\n" +
                           line +
                           "initvel: [0, 0, 0]\ninitatt: [0, 0, 0]\ninitposstd: [0.1, 0.1, 0.1]\n"
                           "initvelstd: [0.1, 0.1, 0.1]\ninitattstd: [1, 1, 2]\nimunoise:\n"
                           "  arw: 0.3\n  vrw: 0.1\n  gbstd: 50\n  abstd: 1000\n  corrtime: 1\n"
                           "antlever: [0, 0, -0.5]\n" +
                           extra_yaml;
  return testing::WriteFile(dir, "kf-gins.yaml", yaml);
}

std::vector<std::vector<double>> ReadRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    rows.emplace_back();
    for (double v; s >> v;) rows.back().push_back(v);
  }
  return rows;
}

TEST(KfginsRunner, StationaryDatasetStaysPutWithOneLinePerImuEpoch) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const KfginsConfig c = LoadKfginsConfig(WriteStationaryDataset(dir));
  const KfginsRunResult r = RunKfgins(c, NavigatorParamsFromKfgins(c));
  EXPECT_EQ(r.imu_epochs, 4000u);
  EXPECT_EQ(r.gnss_records, 20u);  // 1001 … 1020 s, all after the start at 1000.005 s
  EXPECT_EQ(r.gnss_fused, 20u);
  EXPECT_GT(r.mean_nis_pos, 0.0);
  const auto nav = ReadRows(dir + "/out/KF_GINS_Navresult.nav");
  ASSERT_EQ(nav.size(), 4000u);
  ASSERT_EQ(nav.back().size(), 11u);
  EXPECT_NEAR(nav.back()[1], 1020.0, 1e-9);
  LocalTangentFrame f({kLat, kLon, kH});
  const Eigen::Vector3d p = f.ToLocal({nav.back()[2], nav.back()[3], nav.back()[4]});
  EXPECT_LT(p.norm(), 0.02);
  EXPECT_LT(std::abs(nav.back()[8]) + std::abs(nav.back()[9]), 0.05);  // roll, pitch (deg)
  EXPECT_EQ(ReadRows(dir + "/out/KF_GINS_IMU_ERR.txt").back().size(), 7u);
  EXPECT_EQ(ReadRows(dir + "/out/KF_GINS_STD.txt").back().size(), 16u);
}

TEST(KfginsRunner, EndTimeStopsTheRunAndMissingFilesAreErrors) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const KfginsConfig c = LoadKfginsConfig(WriteStationaryDataset(dir, "endtime: 1010\n"));
  EXPECT_EQ(RunKfgins(c, NavigatorParamsFromKfgins(c)).imu_epochs, 2000u);
  KfginsConfig bad = c;
  bad.gnsspath = dir + "/none.txt";
  try {
    RunKfgins(bad, NavigatorParamsFromKfgins(bad));
    FAIL();
  } catch (const DatasetError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/none.txt: cannot open"), std::string::npos);
  }
}

TEST(KfginsRunner, ParametersFollowTheConfigurationsUnits) {
  KfginsConfig c;
  c.imunoise = {0.6, 0.12, 36, 1000, 0, 0, 2};
  c.initposstd_ned_m = {0.1, 0.3, 0.2};
  c.antlever_frd_m = {1, 2, 3};
  const NavigatorParams p = NavigatorParamsFromKfgins(c);
  EXPECT_NEAR(p.ekf.gyro_noise_radps_rthz, 0.01 * std::numbers::pi / 180, 1e-15);  // 0.6°/√h
  EXPECT_NEAR(p.ekf.accel_noise_mps2_rthz, 0.002, 1e-15);
  EXPECT_NEAR(p.ekf.accel_bias_rw_mps3_rthz, 0.01 * std::sqrt(2.0 / 7200), 1e-15);
  EXPECT_DOUBLE_EQ(p.ekf.init_pos_std_m, 0.3);
  EXPECT_EQ(p.ekf.lever_arm_B_m, Eigen::Vector3d(1, -2, -3));
  EXPECT_EQ(p.fusion_horizon.count(), 0);
  // gsstd 0: no gyro scale of the configuration; navd's own z scale prior, no x and y scales
  EXPECT_DOUBLE_EQ(p.ekf.gyro_scale_z_std, EkfParams{}.gyro_scale_z_std);
  EXPECT_EQ(p.ekf.gyro_scale_xy_std, 0.0);
}

TEST(KfginsRunner, TheGyroScaleFactorsAreKfginsOnes) {
  // GIVEN KF-GINS's gyro scale factors: a Gauss–Markov of σ 5000 ppm over 2 h, started at 3000
  KfginsConfig c;
  c.imunoise = {0.6, 0.12, 36, 1000, 5000, 5000, 2};
  const NavigatorParams gm = NavigatorParamsFromKfgins(c);
  c.initsgstd_ppm = Eigen::Vector3d(3000, 2000, 1000);
  const NavigatorParams p = NavigatorParamsFromKfgins(c);
  // THEN the three scales are states: σ gsstd (initsgstd's largest when given), walking as σ·√(2/τ)
  EXPECT_DOUBLE_EQ(gm.ekf.gyro_scale_xy_std, 0.005);
  EXPECT_DOUBLE_EQ(gm.ekf.gyro_scale_z_std, 0.005);
  EXPECT_DOUBLE_EQ(p.ekf.gyro_scale_xy_std, 0.003);
  EXPECT_DOUBLE_EQ(p.ekf.gyro_scale_z_std, 0.003);
  EXPECT_NEAR(p.ekf.gyro_scale_xy_rw_rthz, 0.005 * std::sqrt(2.0 / 7200), 1e-18);
}

TEST(KfginsRunner, TheConfigurationsInitialGyroScaleIsWhereTheEstimateStarts) {
  // GIVEN a vehicle turning in place at 0.1 rad/s for 20 s (2 rad, heading unobservable from the
  // fixes: the antenna is above the IMU), its z gyro's scale 1 % high, once with the
  // configuration saying so (initgyrscale, ppm) and once without
  const auto final_yaw_deg = [](const std::string& extra) {
    const testing::ScopedTempDir tmp;
    const KfginsConfig c = LoadKfginsConfig(WriteStationaryDataset(tmp.path, extra, 0.1 * 1.01));
    RunKfgins(c, NavigatorParamsFromKfgins(c));
    return ReadRows(tmp.path + "/out/KF_GINS_Navresult.nav").back()[10];
  };
  const double told = final_yaw_deg("initgyrscale: [0, 0, 10000]\n");
  const double untold = final_yaw_deg("");
  // THEN told, navd turns the 2 rad the vehicle turned (the 1 % divided out); untold, 1 % more
  const double turned_deg = 2.0 * 180.0 / std::numbers::pi;
  EXPECT_NEAR(told, turned_deg - 360.0 * std::round(turned_deg / 360.0), 0.1);
  EXPECT_NEAR(untold - told, 0.01 * turned_deg, 0.15);
}

}  // namespace
}  // namespace hil::estimator::datasets

#include "hil/estimator/datasets/kfgins_config.h"

#include <gtest/gtest.h>

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

// the layout of KF-GINS's own configuration files (comments, quotes, one nested block)
const char* kConfig = R"(# KF-GINS configuration
imupath: "dataset/IMU.txt"   # increments
gnsspath: 'dataset/GNSS.txt'
outputpath: "dataset"
imudatalen: 7
imudatarate: 200
starttime: 456300
endtime: -1
initpos: [ 30.4447873701, 114.4718632047, 20.899 ]
initvel: [ 0.0, 0.0, 0.0 ]
initatt: [ 0.854, -2.0345, 185.702 ]
initposstd: [ 0.005, 0.004, 0.008 ]
initvelstd: [ 0.003, 0.004, 0.004 ]
initattstd: [ 0.003, 0.003, 0.023 ]
initgyrbias: [ 0, 0, 0 ]    # [deg/h]
initaccbias: [ 0, 0, 0 ]    # [mGal]
initgyrscale: [ 0, 0, 0 ]   # [ppm]
initaccscale: [ 0, 0, 0 ]   # [ppm]
imunoise:
  arw: [0.003, 0.003, 0.003]          # [deg/sqrt(hr)]
  vrw: [0.03, 0.03, 0.03]
  gbstd: [0.027, 0.025, 0.027]
  abstd: [15.0, 15.0, 15.0]
  gsstd: [300.0, 300.0, 300.0]
  asstd: [300.0, 300.0, 300.0]
  corrtime: 4.0
antlever: [ 0.136, -0.301, -0.184 ]
odo: unused
)";

TEST(KfginsConfig, ReadsEveryKeyInTheFilesUnits) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const KfginsConfig c = LoadKfginsConfig(testing::WriteFile(dir, "kf-gins.yaml", kConfig));
  EXPECT_EQ(c.imupath, "dataset/IMU.txt");
  EXPECT_EQ(c.gnsspath, "dataset/GNSS.txt");
  EXPECT_EQ(c.imudatalen, 7);
  EXPECT_DOUBLE_EQ(c.imudatarate_hz, 200);
  EXPECT_DOUBLE_EQ(c.starttime_s, 456300);
  EXPECT_DOUBLE_EQ(c.endtime_s, -1);
  EXPECT_DOUBLE_EQ(c.initpos_deg_deg_m.y(), 114.4718632047);
  EXPECT_DOUBLE_EQ(c.initatt_rpy_deg.z(), 185.702);
  EXPECT_DOUBLE_EQ(c.initposstd_ned_m.z(), 0.008);
  EXPECT_DOUBLE_EQ(c.imunoise.abstd_mgal, 15.0);
  EXPECT_DOUBLE_EQ(c.imunoise.gbstd_deg_hr, 0.027);  // the largest of the three axes
  EXPECT_DOUBLE_EQ(c.imunoise.asstd_ppm, 300.0);
  EXPECT_DOUBLE_EQ(c.imunoise.corrtime_hr, 4.0);
  EXPECT_DOUBLE_EQ(c.antlever_frd_m.y(), -0.301);
  EXPECT_FALSE(c.initbgstd_deg_hr.has_value());
}

TEST(KfginsConfig, NoiseMayBeOneNumberForTheThreeAxes) {
  const testing::ScopedTempDir tmp;
  std::string text = kConfig;
  text.replace(text.find("arw: [0.003, 0.003, 0.003]"), 26, "arw: 0.004");
  const KfginsConfig c = LoadKfginsConfig(testing::WriteFile(tmp.path, "scalar.yaml", text));
  EXPECT_DOUBLE_EQ(c.imunoise.arw_deg_rthr, 0.004);
  text.replace(text.find("arw: 0.004"), 10, "arw: [0.1, 0.2]");
  const std::string path = testing::WriteFile(tmp.path, "two.yaml", text);
  try {
    LoadKfginsConfig(path);
    FAIL();
  } catch (const DatasetError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":20: imunoise.arw: expected 3 values, got 2");
  }
}

TEST(KfginsConfig, BadValuesNameFileLineAndKey) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  std::string text = kConfig;
  text.replace(text.find("[ 0.136, -0.301, -0.184 ]"), 25, "[0.1, 0.2]");
  const std::string path = testing::WriteFile(dir, "short.yaml", text);
  try {
    LoadKfginsConfig(path);
    FAIL();
  } catch (const DatasetError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":27: antlever: expected 3 values, got 2");
  }
  text = kConfig;
  text.replace(text.find("arw: [0.003, 0.003, 0.003]"), 26, "arw: fast");
  EXPECT_THROW(LoadKfginsConfig(testing::WriteFile(dir, "nan.yaml", text)), DatasetError);
  text = kConfig;
  text.erase(text.find("starttime: 456300\n"), 18);
  try {
    LoadKfginsConfig(testing::WriteFile(dir, "missing.yaml", text));
    FAIL();
  } catch (const DatasetError& e) {
    EXPECT_NE(std::string(e.what()).find("starttime: missing"), std::string::npos);
  }
}

}  // namespace
}  // namespace hil::estimator::datasets

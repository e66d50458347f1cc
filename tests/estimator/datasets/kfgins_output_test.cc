#include "hil/estimator/datasets/kfgins_output.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "hil/estimator/datasets/dataset_error.h"

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(KfginsOutputWriter, WritesTheThreeFilesOneLineEach) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  KfginsOutputWriter w(dir);
  KfginsEpoch e;
  e.sow = 456300.005;
  e.lat_deg = 30.4447873701;
  e.lon_deg = -114.5;
  e.height_m = 20.9;
  e.vel_ned_mps = {1, -2, 0.5};
  e.rpy_deg = {1, 2, -179};
  e.gyro_bias_frd_deg_hr = {10, 20, 30};
  e.accel_bias_frd_mgal = {100, 200, 300};
  e.pos_std_ned_m.setConstant(0.01);
  w.Write(e);
  w.Close();
  EXPECT_EQ(ReadAll(dir + "/KF_GINS_Navresult.nav"),
            "0 456300.005000 30.44478737010 -114.50000000000 20.900000 1.000000 -2.000000 "
            "0.500000 1.00000000 2.00000000 -179.00000000\n");
  EXPECT_EQ(ReadAll(dir + "/KF_GINS_IMU_ERR.txt"),
            "456300.005000 10.000000 20.000000 30.000000 100.000000 200.000000 300.000000\n");
  std::istringstream std_line(ReadAll(dir + "/KF_GINS_STD.txt"));
  int columns = 0;
  for (double v; std_line >> v;) ++columns;
  EXPECT_EQ(columns, 16);
}

TEST(KfginsOutputWriter, UnwritableFolderIsAnError) {
  EXPECT_THROW({ KfginsOutputWriter w("/nonexistent/out"); }, DatasetError);
}

}  // namespace
}  // namespace hil::estimator::datasets

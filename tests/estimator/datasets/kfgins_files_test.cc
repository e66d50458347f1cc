#include "hil/estimator/datasets/kfgins_files.h"

#include <gtest/gtest.h>

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

std::string ErrorOf(const std::string& path, bool imu) {
  try {
    if (imu) {
      KfginsImuReader r(path, 7);
      KfginsImuRecord rec;
      while (r.Next(rec)) {
      }
    } else {
      KfginsGnssReader r(path);
      KfginsGnssRecord rec;
      while (r.Next(rec)) {
      }
    }
  } catch (const DatasetError& e) {
    return e.what();
  }
  return "";
}

TEST(KfginsImuReader, ReadsIncrementsInFrd) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  KfginsImuReader r(testing::WriteFile(dir, "imu.txt",
                                       "456300.005 1e-5 -2e-5 3e-5 0.001 -0.002 -0.049\n"
                                       "456300.010,1e-5,-2e-5,3e-5,0.001,-0.002,-0.049\n"),
                    7);
  KfginsImuRecord rec;
  ASSERT_TRUE(r.Next(rec));
  EXPECT_DOUBLE_EQ(rec.sow, 456300.005);
  EXPECT_DOUBLE_EQ(rec.dtheta_frd_rad.y(), -2e-5);
  EXPECT_DOUBLE_EQ(rec.dvel_frd_mps.z(), -0.049);
  ASSERT_TRUE(r.Next(rec));
  EXPECT_DOUBLE_EQ(rec.sow, 456300.010);
  EXPECT_FALSE(r.Next(rec));
}

TEST(KfginsImuReader, BadLinesNameFileLineAndField) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const std::string good = "1.000 0 0 0 0 0 -0.049\n";
  std::string p = testing::WriteFile(dir, "short.txt", good + "1.005 0 0 0 0 0\n");
  EXPECT_EQ(ErrorOf(p, true), p + ":2: dvel_z: short line (6 of 7 columns)");
  p = testing::WriteFile(dir, "nan.txt", good + "1.005 0 0 NaN 0 0 -0.049\n");
  EXPECT_EQ(ErrorOf(p, true), p + ":2: dtheta_z: not finite: 'NaN'");
  p = testing::WriteFile(dir, "back.txt", good + "0.995 0 0 0 0 0 -0.049\n");
  EXPECT_EQ(ErrorOf(p, true), p + ":2: sow: time goes backwards (0.995000 after 1.000000)");
  p = testing::WriteFile(dir, "repeat.txt", good + good);
  EXPECT_EQ(ErrorOf(p, true), p + ":2: sow: time repeats (1.000000 after 1.000000)");
}

TEST(KfginsGnssReader, ReadsPositionAndOptionalVelocity) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  KfginsGnssReader r(
      testing::WriteFile(dir, "gnss.txt",
                         "456300 30.44 114.47 20.9 0.01 0.02 0.03\n"
                         "456301 30.44 114.47 20.9 0.01 0.02 0.03 1.0 -1.0 0.1 0.05 0.05 0.1\n"));
  KfginsGnssRecord g;
  ASSERT_TRUE(r.Next(g));
  EXPECT_FALSE(g.has_velocity);
  EXPECT_DOUBLE_EQ(g.std_ned_m.y(), 0.02);
  ASSERT_TRUE(r.Next(g));
  EXPECT_TRUE(g.has_velocity);
  EXPECT_DOUBLE_EQ(g.vel_ned_mps.y(), -1.0);
  EXPECT_DOUBLE_EQ(g.vel_std_ned_mps.z(), 0.1);
}

TEST(KfginsGnssReader, BadLinesNameFileLineAndField) {
  const testing::ScopedTempDir tmp;
  const std::string& dir = tmp.path;
  const std::string good = "10 30 114 20 0.01 0.01 0.02\n";
  std::string p = testing::WriteFile(dir, "short.txt", good + "11 30 114 20 0.01\n");
  EXPECT_EQ(ErrorOf(p, false), p + ":2: std_e: short line (5 columns; 7, or 13 with velocity)");
  p = testing::WriteFile(dir, "neg.txt", good + "11 30 114 20 0.01 -0.01 0.02\n");
  EXPECT_EQ(ErrorOf(p, false), p + ":2: std_e: negative σ");
  p = testing::WriteFile(dir, "back.txt", good + "9 30 114 20 0.01 0.01 0.02\n");
  EXPECT_NE(ErrorOf(p, false).find(":2: sow: time goes backwards"), std::string::npos);
  p = testing::WriteFile(dir, "inf.txt", good + "11 inf 114 20 0.01 0.01 0.02\n");
  EXPECT_EQ(ErrorOf(p, false), p + ":2: lat: not finite: 'inf'");
}

}  // namespace
}  // namespace hil::estimator::datasets

#pragma once
/// @file
/// KF-GINS's three result files, one line per IMU epoch, under KF-GINS's names in outputpath:
///   KF_GINS_Navresult.nav  week sow lat lon h vN vE vD roll pitch yaw   (deg, m, m/s, deg)
///   KF_GINS_IMU_ERR.txt    sow gyro bias xyz (°/h) accelerometer bias xyz (mGal), body FRD
///   KF_GINS_STD.txt        sow σ of position NED (m), velocity NED (m/s), attitude (deg),
///                          gyro bias (°/h), accelerometer bias (mGal)
/// navd has no scale-factor states, so the scale-factor columns of KF-GINS's IMU_ERR and STD files
/// are left out (13 → 7 and 22 → 16 columns). Numbers are formatted with std::to_chars into a fixed
/// buffer (no allocation per line).

#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::estimator::datasets {

/// One epoch of navd's solution in KF-GINS's frames and units.
struct KfginsEpoch {
  int week = 0;  ///< KF-GINS writes 0 (its files carry no week)
  double sow = 0;
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_deg = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_frd_deg_hr = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_frd_mgal = Eigen::Vector3d::Zero();
  Eigen::Vector3d pos_std_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_std_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d att_std_deg = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_std_deg_hr = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_std_mgal = Eigen::Vector3d::Zero();
};

class KfginsOutputWriter {
 public:
  /// Creates the three files in `dir` (which must exist).
  /// @throws DatasetError when one cannot be created.
  explicit KfginsOutputWriter(const std::string& dir);
  ~KfginsOutputWriter();
  KfginsOutputWriter(const KfginsOutputWriter&) = delete;
  KfginsOutputWriter& operator=(const KfginsOutputWriter&) = delete;

  void Write(const KfginsEpoch& e);
  /// Flushes and closes; @throws DatasetError on a write error (a full disk).
  void Close();

  static constexpr const char* kNavFile = "KF_GINS_Navresult.nav";
  static constexpr const char* kImuErrFile = "KF_GINS_IMU_ERR.txt";
  static constexpr const char* kStdFile = "KF_GINS_STD.txt";

 private:
  /// a file's lines, formatted straight into one block that goes out whole (no stdio copy)
  struct Block {
    std::FILE* file = nullptr;
    std::vector<char> bytes;
    std::size_t used = 0;
    char* Line();  ///< room for one more line (the block goes out first when it has none)
    void Flush();
  };
  std::string dir_;
  Block nav_, err_, std_;
};

}  // namespace hil::estimator::datasets

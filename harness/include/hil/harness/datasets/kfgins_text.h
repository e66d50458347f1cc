#pragma once
/// @file
/// The harness's own writer and reader of KF-GINS's text formats (independent of navd's readers in
/// hil::estimator::datasets, so each judges the other): IMU increments, GNSS fixes, PVA (truth.nav
/// and KF_GINS_Navresult.nav: week sow lat lon h vN vE vD roll pitch yaw) and the YAML
/// configuration. Frames: the harness's ENU / body FLU in, KF-GINS's NED / FRD in the files.

#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hil::harness {

struct KfginsImuIncrement {
  Eigen::Vector3d dtheta_flu_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_flu_mps = Eigen::Vector3d::Zero();
};

struct KfginsFix {
  double sow = 0, lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d std_ned_m = Eigen::Vector3d::Zero();
};

/// Position, velocity and attitude of the IMU at one time.
struct KfginsPva {
  double sow = 0, lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d v_enu_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_enu_flu = Eigen::Quaterniond::Identity();
};

/// What a written configuration says besides the file names.
struct KfginsYaml {
  double imudatarate_hz = 200, starttime_s = 0;
  KfginsPva init;
  Eigen::Vector3d initposstd_m{0.05, 0.05, 0.05}, initvelstd_mps{0.05, 0.05, 0.05};
  Eigen::Vector3d initattstd_deg{0.5, 0.5, 1.0};
  Eigen::Vector3d antlever_flu_m = Eigen::Vector3d::Zero();
  double arw_deg_rthr = 0.3, vrw_mps_rthr = 0.1, gbstd_deg_hr = 200, abstd_mgal = 5000;
  double gsstd_ppm = 1000, asstd_ppm = 1000, corrtime_hr = 1;
  /// initial IMU errors (body FRD, KF-GINS's units) and their σ (written when > 0)
  Eigen::Vector3d initgyrbias_deg_hr = Eigen::Vector3d::Zero();
  Eigen::Vector3d initaccbias_mgal = Eigen::Vector3d::Zero();
  double initbgstd_deg_hr = 0, initbastd_mgal = 0;
};

/// KF-GINS's roll, pitch, yaw (degrees, NED/FRD, yaw in (−180, 180]) of an ENU/FLU attitude.
Eigen::Vector3d KfginsEulerDeg(const Eigen::Quaterniond& q_enu_flu);

/// Writes IMU.txt, GNSS.txt and truth.nav (and kf-gins.yaml on request) in a folder.
class KfginsTextFiles {
 public:
  /// @throws std::runtime_error when a file cannot be created.
  explicit KfginsTextFiles(const std::string& dir);
  ~KfginsTextFiles();
  KfginsTextFiles(const KfginsTextFiles&) = delete;
  KfginsTextFiles& operator=(const KfginsTextFiles&) = delete;

  void WriteImu(double sow, const KfginsImuIncrement& inc);
  void WriteGnss(const KfginsFix& f);
  /// The same fix with its velocity (NED, m/s) into GNSS-POSVEL.txt (13 columns, KF-GINS-Matlab's
  /// position-and-velocity layout; created on first use).
  void WriteGnssPosVel(const KfginsFix& f, const Eigen::Vector3d& v_ned_mps,
                       const Eigen::Vector3d& v_std_ned_mps);
  void WriteTruth(const KfginsPva& p);
  /// A configuration (default kf-gins.yaml) naming IMU.txt and a GNSS file (relative to the
  /// folder) and outputpath "result".
  void WriteConfig(const KfginsYaml& y, const std::string& gnss_file = "GNSS.txt",
                   const std::string& name = "kf-gins.yaml") const;
  /// @throws std::runtime_error on a write error.
  void Close();

 private:
  std::string dir_;
  std::FILE* imu_ = nullptr;
  std::FILE* gnss_ = nullptr;
  std::FILE* truth_ = nullptr;
  std::FILE* posvel_ = nullptr;
};

/// One line of a .nav file (truth.nav, KF_GINS_Navresult.nav).
struct KfginsNavLine {
  double sow = 0, lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d v_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d rpy_deg = Eigen::Vector3d::Zero();
};
/// Reads a .nav file. @throws std::runtime_error naming file and line for a bad line.
std::vector<KfginsNavLine> ReadKfginsNav(const std::string& path);

}  // namespace hil::harness

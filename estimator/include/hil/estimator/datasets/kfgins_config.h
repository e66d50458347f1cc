#pragma once
/// @file
/// A KF-GINS configuration file (i2Nav-WHU/KF-GINS's YAML, read as it is): the file paths, the time
/// span, the initial state and its σ, the IMU error model and the antenna lever arm, in the file's
/// own units and frames (NED, FRD body; degrees, °/√h, m/s/√h, °/h, mGal, ppm, hours).
/// The reader takes the YAML subset these files use: `key: value`, `key: [a, b, c]` and one level
/// of nested keys (`imunoise:`), with `#` comments. Unknown keys are kept out (KF-GINS ignores them
/// too); a missing required key, a value that is not a number or a list of the wrong length is a
/// DatasetError naming the file, the line and the key.

#include <optional>
#include <string>

#include <Eigen/Core>

#include "hil/estimator/datasets/dataset_error.h"

namespace hil::estimator::datasets {

/// imunoise: the IMU error model (KF-GINS units). KF-GINS gives arw … asstd per axis ([x, y, z]);
/// navd's noise is the same on the three axes, so it keeps the largest (one number is read too).
struct KfginsImuNoise {
  double arw_deg_rthr = 0;  ///< gyro angle random walk, °/√h
  double vrw_mps_rthr = 0;  ///< accelerometer velocity random walk, m/s/√h
  double gbstd_deg_hr = 0;  ///< gyro bias σ (first-order Gauss–Markov), °/h
  double abstd_mgal = 0;    ///< accelerometer bias σ, mGal
  double gsstd_ppm = 0;     ///< gyro scale-factor σ, ppm (navd's gyro scale states)
  double asstd_ppm = 0;     ///< accelerometer scale-factor σ, ppm (not used: see kfgins.md)
  double corrtime_hr = 1;   ///< correlation time of every bias and scale state, hours
};

struct KfginsConfig {
  std::string config_path;                    ///< the file itself (for messages)
  std::string imupath, gnsspath, outputpath;  ///< as written in the file
  int imudatalen = 7;                         ///< columns of an IMU line (8: with odometer speed)
  double imudatarate_hz = 200;
  double starttime_s = 0;  ///< GPS seconds of week; the initial state is valid here
  double endtime_s = -1;   ///< −1: to the end of the IMU file
  Eigen::Vector3d initpos_deg_deg_m = Eigen::Vector3d::Zero();  ///< lat, lon, ellipsoidal height
  Eigen::Vector3d initvel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d initatt_rpy_deg = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw (NED, FRD)
  Eigen::Vector3d initposstd_ned_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d initvelstd_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d initattstd_deg = Eigen::Vector3d::Zero();
  /// optional initial biases (FRD; the runner starts the filter's estimates there, zero without)
  std::optional<Eigen::Vector3d> initgyrbias_deg_hr, initaccbias_mgal;
  /// optional initial bias σ (default: imunoise gbstd / abstd)
  std::optional<Eigen::Vector3d> initbgstd_deg_hr, initbastd_mgal;
  /// optional initial gyro scale-factor errors and their σ (ppm; default 0 and imunoise gsstd)
  std::optional<Eigen::Vector3d> initgyrscale_ppm, initsgstd_ppm;
  KfginsImuNoise imunoise;
  Eigen::Vector3d antlever_frd_m = Eigen::Vector3d::Zero();  ///< GNSS antenna in the IMU frame

  /// A path of the file resolved as KF-GINS does (relative to the working directory), or, when no
  /// such file exists there, relative to the configuration's folder.
  std::string Resolve(const std::string& path) const;
};

/// @throws DatasetError for a file that cannot be read or a bad or missing key.
KfginsConfig LoadKfginsConfig(const std::string& path);

}  // namespace hil::estimator::datasets

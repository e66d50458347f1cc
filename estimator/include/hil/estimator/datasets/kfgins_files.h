#pragma once
/// @file
/// KF-GINS's input text files, read one record at a time (no allocation per line):
///   IMU:  sow dθx dθy dθz dvx dvy dvz [odometer speed]  — GPS seconds of week, increments over
///         the interval that ends at sow, rad and m/s, body FRD;
///   GNSS: sow lat lon h σN σE σD — degrees, ellipsoidal metres, 1σ metres of the antenna; a line
///         of 13 columns adds vN vE vD σvN σvE σvD (m/s; KF-GINS-Matlab's position-and-velocity
///         files).
/// A short line, a field that is not a finite number, a negative σ or a time that does not
/// increase is a DatasetError naming the file, the line and the field.

#include <string>
#include <string_view>

#include <Eigen/Core>

#include "hil/estimator/datasets/text_line_reader.h"

namespace hil::estimator::datasets {

struct KfginsImuRecord {
  double sow = 0;
  Eigen::Vector3d dtheta_frd_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_frd_mps = Eigen::Vector3d::Zero();
  double odometer_mps = 0;  ///< the 8th column when imudatalen is 8
};

struct KfginsGnssRecord {
  double sow = 0;
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d std_ned_m = Eigen::Vector3d::Zero();
  bool has_velocity = false;
  Eigen::Vector3d vel_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel_std_ned_mps = Eigen::Vector3d::Zero();
};

class KfginsImuReader {
 public:
  /// `columns`: imudatalen (7, or 8 with an odometer column).
  KfginsImuReader(const std::string& path, int columns);
  /// The next record; false at the end of the file.
  bool Next(KfginsImuRecord& r);
  long line_number() const { return reader_.line_number(); }

 private:
  TextLineReader reader_;
  int columns_;
  bool have_prev_ = false;
  double prev_sow_ = 0;
};

class KfginsGnssReader {
 public:
  explicit KfginsGnssReader(const std::string& path);
  bool Next(KfginsGnssRecord& r);
  long line_number() const { return reader_.line_number(); }

 private:
  TextLineReader reader_;
  bool have_prev_ = false;
  double prev_sow_ = 0;
};

}  // namespace hil::estimator::datasets

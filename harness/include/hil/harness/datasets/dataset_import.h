#pragma once
/// @file
/// `hil dataset import`: real logs into the KF-GINS files navd (`navd --kfgins`) and KF-GINS read.
/// Inputs: an RTKLIB solution file as the reference (truth), the GNSS input from an RTKLIB
/// solution file (the same one by default) or a u-blox UBX log, and a raw IMU CSV dated by its
/// RTKLIB TIMETAG file. Steps: the sensor tick fitted to the tags; sensor axes to body FRD and
/// units to SI as told; rest at the start → gyro bias, roll, pitch, accelerometer bias along
/// gravity; the IMU's lag behind GPS time by cross-correlation of the gyro's heading rate with the
/// GNSS course rate (or a given offset); the yaw from velocity increments; outage windows.
/// Output folder: IMU.txt, GNSS.txt (and GNSS-POSVEL.txt with velocities), truth.nav,
/// kf-gins.yaml (and kf-gins-posvel.yaml), outages.txt, import_report.txt.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/datasets/imu_alignment.h"
#include "hil/harness/datasets/imu_csv.h"
#include "hil/harness/datasets/imu_timing.h"
#include "hil/harness/datasets/outage_windows.h"

namespace hil::harness {

/// KF-GINS noise and initial σ written into the configuration. Defaults: ICM-45686 class (see
/// the README's `hil dataset import`): ARW and VRW from the datasheet's noise densities
/// (3.8 mdps/√Hz → 0.228 °/√h; 70 µg/√Hz → 0.0412 m/s/√h); the bias and scale-factor figures are
/// chosen here (the datasheet gives no bias instability).
struct ImportNoise {
  double arw_deg_rthr = 0.228, vrw_mps_rthr = 0.0412;
  double gbstd_deg_hr = 50, abstd_mgal = 1000, gsstd_ppm = 5000, asstd_ppm = 5000, corrtime_hr = 1;
  double initbgstd_deg_hr = 100, initbastd_mgal = 5000;
  Eigen::Vector3d initposstd_m{0.05, 0.05, 0.1}, initvelstd_mps{0.05, 0.05, 0.05};
  Eigen::Vector3d initattstd_deg{1, 1, 5};
};

struct DatasetImportOptions {
  std::string reference_pos;       ///< RTKLIB .pos: the truth
  std::string gnss_pos, gnss_ubx;  ///< GNSS input: one of them (default: reference_pos)
  bool ubx_height_msl = false;     ///< UBX: hMSL instead of the height above the ellipsoid
  std::string imu_csv, imu_tag;    ///< imu_tag default: imu_csv + ".tag"
  int tag_fpos_bytes = 4;
  ImuCsvOptions csv;
  std::string imu_axes = "x,y,z";  ///< body FRD x, y, z as signed sensor axes, e.g. "x,-y,-z"
  Eigen::Vector3d lever_frd_m = Eigen::Vector3d::Zero();  ///< antenna in the body, FRD
  std::optional<double> imu_lag_s;                        ///< given; else estimated
  double max_lag_s = 1.0;
  int reference_max_q = 2, gnss_max_q = 2;  ///< RTKLIB Q accepted (1 fix, 2 float)
  double lag_min_speed_mps = 0.5;
  OutagePlan outages;
  bool have_outages = false;
  AlignmentOptions align;
  ImportNoise noise;
};

struct DatasetImportResult {
  std::string report;  ///< what import_report.txt holds
  std::size_t imu_lines = 0, gnss_lines = 0, truth_lines = 0;
  ImuTickFit tick_fit;
  std::optional<ImuLagEstimate> lag;
  double lag_s = 0;
  ImuAlignment alignment;
  std::vector<OutageWindow> windows;
};

/// @throws ImportInputError (file, line, field) for bad input, std::runtime_error when the data
/// do not allow the import (no rest at the start, no overlap of IMU and GNSS…).
DatasetImportResult ImportDataset(const DatasetImportOptions& o, const std::string& dir);

/// "x,-y,-z" → the matrix taking sensor axes to body FRD. @throws std::invalid_argument.
Eigen::Matrix3d ParseImuAxes(const std::string& axes);

}  // namespace hil::harness

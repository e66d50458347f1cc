#include "hil/estimator/datasets/kfgins_files.h"

#include <cstdio>

namespace hil::estimator::datasets {
namespace {

constexpr const char* kImuFields[] = {"sow",    "dtheta_x", "dtheta_y", "dtheta_z",
                                      "dvel_x", "dvel_y",   "dvel_z",   "odometer"};
constexpr const char* kGnssFields[] = {"sow",    "lat",    "lon",   "h",     "std_n",
                                       "std_e",  "std_d",  "vel_n", "vel_e", "vel_d",
                                       "std_vn", "std_ve", "std_vd"};

// the time check both files share
void CheckTime(const TextLineReader& r, double sow, bool& have_prev, double& prev_sow) {
  if (have_prev && !(sow > prev_sow)) {
    char msg[160];
    std::snprintf(msg, sizeof msg, "sow: time %s (%.6f after %.6f)",
                  sow == prev_sow ? "repeats" : "goes backwards", sow, prev_sow);
    r.Fail(msg);
  }
  have_prev = true;
  prev_sow = sow;
}

}  // namespace

KfginsImuReader::KfginsImuReader(const std::string& path, int columns)
    : reader_(path), columns_(columns) {}

bool KfginsImuReader::Next(KfginsImuRecord& r) {
  std::string_view line;
  if (!reader_.Next(line)) return false;
  double v[8];
  const int n = reader_.ParseNumbers(line, v, columns_, kImuFields);
  if (n < columns_) {
    reader_.Fail(std::string(kImuFields[n]) + ": short line (" + std::to_string(n) + " of " +
                 std::to_string(columns_) + " columns)");
  }
  CheckTime(reader_, v[0], have_prev_, prev_sow_);
  r.sow = v[0];
  r.dtheta_frd_rad = Eigen::Vector3d(v[1], v[2], v[3]);
  r.dvel_frd_mps = Eigen::Vector3d(v[4], v[5], v[6]);
  r.odometer_mps = columns_ > 7 ? v[7] : 0.0;
  return true;
}

KfginsGnssReader::KfginsGnssReader(const std::string& path) : reader_(path) {}

bool KfginsGnssReader::Next(KfginsGnssRecord& r) {
  std::string_view line;
  if (!reader_.Next(line)) return false;
  double v[13];
  const int n = reader_.ParseNumbers(line, v, 13, kGnssFields);
  if (n < 7 || (n > 7 && n < 13)) {
    reader_.Fail(std::string(kGnssFields[n]) + ": short line (" + std::to_string(n) +
                 " columns; 7, or 13 with velocity)");
  }
  CheckTime(reader_, v[0], have_prev_, prev_sow_);
  if (v[1] < -90 || v[1] > 90) reader_.Fail("lat: outside [-90, 90]");
  for (int i = 4; i < 7; ++i)
    if (v[i] < 0) reader_.Fail(std::string(kGnssFields[i]) + ": negative σ");
  r.sow = v[0];
  r.lat_deg = v[1];
  r.lon_deg = v[2];
  r.height_m = v[3];
  r.std_ned_m = Eigen::Vector3d(v[4], v[5], v[6]);
  r.has_velocity = n == 13;
  if (r.has_velocity) {
    for (int i = 10; i < 13; ++i)
      if (v[i] < 0) reader_.Fail(std::string(kGnssFields[i]) + ": negative σ");
    r.vel_ned_mps = Eigen::Vector3d(v[7], v[8], v[9]);
    r.vel_std_ned_mps = Eigen::Vector3d(v[10], v[11], v[12]);
  }
  return true;
}

}  // namespace hil::estimator::datasets

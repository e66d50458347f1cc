#include "hil/harness/characterize/imu_log_readers.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "hil/harness/datasets/capture_imu.h"

#include "log_fields.h"

namespace hil::harness {
namespace {

constexpr const char* kKfginsFields[] = {"sow",    "dtheta_x", "dtheta_y", "dtheta_z",
                                         "dvel_x", "dvel_y",   "dvel_z",   "odo"};

std::vector<std::string_view> SplitBlankTabComma(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() &&
           (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '\r'))
      ++i;
    const std::size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',' &&
           line[i] != '\r')
      ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

bool EndsWith(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

double ParseFiniteField(std::string_view text, const std::string& where, const char* field) {
  const std::string s(text);
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty() || !std::isfinite(v))
    throw std::runtime_error(where + ": field " + field + ": '" + s + "' is not a finite number");
  return v;
}

ImuSeries ReadKfginsImuText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  ImuSeries s;
  s.format = "kfgins";
  s.notes.push_back("KF-GINS IMU text: increments over each interval, the file's axes (FRD)");
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#' || line[first] == '%') continue;
    const std::vector<std::string_view> f = SplitBlankTabComma(line);
    const std::string where = path + ":" + std::to_string(n);
    if (f.size() != 7 && f.size() != 8)
      throw std::runtime_error(where + ": expected 7 or 8 columns (sow dθxyz dvxyz [odo]), found " +
                               std::to_string(f.size()));
    double v[8];
    for (std::size_t k = 0; k < f.size(); ++k)
      v[k] = ParseFiniteField(f[k], where, kKfginsFields[k]);
    if (!s.t_s.empty() && !(v[0] > s.t_s.back()))
      throw std::runtime_error(where + ": field sow: time does not increase");
    if (!s.t_s.empty()) {
      const double dt = v[0] - s.t_s.back();
      s.gyro_radps.emplace_back(v[1] / dt, v[2] / dt, v[3] / dt);
      s.accel_mps2.emplace_back(v[4] / dt, v[5] / dt, v[6] / dt);
    }
    s.t_s.push_back(v[0]);
  }
  if (s.size() < 2) throw std::runtime_error(path + ": fewer than 3 IMU lines");
  return s;
}

ImuSeries ReadCaptureImuSeries(const std::string& cap_path) {
  const CaptureImu cap = ReadCaptureImu(cap_path);
  ImuSeries s;
  s.format = "capture";
  std::size_t dropped = 0;
  Eigen::Vector3d last_w = Eigen::Vector3d::Zero(), last_a = Eigen::Vector3d::Zero();
  for (const CaptureImuPoint& p : cap.points) {
    if (!s.t_s.empty() && !(p.t_gps_s > s.t_s.back())) {
      ++dropped;
      continue;
    }
    if (!s.t_s.empty()) {
      s.gyro_radps.push_back(last_w);
      s.accel_mps2.push_back(last_a);
    }
    s.t_s.push_back(p.t_gps_s);
    last_w = p.w_flu_radps;
    last_a = p.a_flu_mps2;
  }
  if (s.size() < 2) throw std::runtime_error(cap_path + ": fewer than 3 timed IMU samples");
  s.notes.push_back(
      "MCU capture: IMU_SAMPLE point samples on GPS time (TIME_PULSE), FLU, each held "
      "until the next; " +
      std::to_string(cap.frames) + " frames, " + std::to_string(cap.bad_frames) + " bad, " +
      std::to_string(cap.resets) + " resets, " + std::to_string(dropped) +
      " samples without a later time");
  return s;
}

ImuSeries ReadImuLog(const std::string& path, const std::string& format) {
  std::string f = format;
  if (f == "auto") {
    if (EndsWith(path, ".cap"))
      f = "capture";
    else if (std::ifstream(path + ".tag").good())
      f = "csv-timetag";
    else
      f = "kfgins";
  }
  if (f == "capture") return ReadCaptureImuSeries(path);
  if (f == "csv-timetag") return ReadCsvTimetag(path, path + ".tag");
  if (f == "kfgins") return ReadKfginsImuText(path);
  throw std::runtime_error("unknown IMU log format '" + format + "'");
}

}  // namespace hil::harness

#pragma once
/// @file
/// Raw IMU samples from a CSV log: one sample a line, comma-separated, three accelerations, three
/// angular rates and the sensor's own tick, in columns and units given as options. Each line's
/// byte position in the file is kept so that an RTKLIB time tag (rtklib_timetag.h) can date it.
/// A line cut by the start or the end of the log (the first and the last line, as a serial
/// logger leaves them) is skipped and counted; any other bad line is an error naming the file,
/// the line and the field.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

struct ImuCsvOptions {
  int accel_column = 0;  ///< first of three columns (0-based)
  int gyro_column = 3;
  int tick_column = 6;
  double accel_scale = 9.80665;  ///< to m/s²: 9.80665 for g (standard gravity), 1 for m/s²
  double gyro_scale = 0.017453292519943295;  ///< to rad/s: π/180 for °/s, 1 for rad/s
  double tick_s = 1e-3;                      ///< seconds per tick count
};

struct ImuCsvSample {
  double tick_s = 0;  ///< the sensor's tick in seconds (unwrapped: monotonic)
  Eigen::Vector3d f_sensor_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_sensor_radps = Eigen::Vector3d::Zero();
  long line = 0;
  std::uint64_t end_pos = 0;  ///< bytes of the file up to and including the line's newline
};

struct ImuCsv {
  std::vector<ImuCsvSample> samples;
  long lines = 0, cut_lines = 0;  ///< cut: the first or last line, incomplete
  bool has_cr = false;            ///< the file's lines end in CR LF
  std::uint64_t file_bytes = 0, newlines = 0;
};

/// @throws ImportInputError for a bad line (wrong field count, not a number, a tick that does
/// not increase) other than a cut first or last line.
ImuCsv ReadImuCsv(const std::string& path, const ImuCsvOptions& o);

}  // namespace hil::harness

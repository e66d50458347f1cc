#pragma once
/// @file
/// The IMU logs hil characterize reads, each into an ImuSeries (axes as the log has them):
/// - KF-GINS IMU text (estimator/doc/kfgins.md): `sow dθx dθy dθz dvx dvy dvz [odo]`, increments
///   over the interval ending at sow (rad, m/s); blank-, tab- or comma-separated, `#`/`%` lines
///   skipped; the first line only opens the first interval.
/// - IMU CSV with an RTKLIB TIMETAG file (`PATH.tag`): `ax,ay,az` [g], `gx,gy,gz` [°/s], the
///   sensor's millisecond tick. Samples are timed by the sensor tick (held until the next sample)
///   and put on GPST by the tag file: RTKLIB's stream writer records, after a 64-byte header
///   (text id, the start tick in its last 4 bytes) and the open time (uint32 seconds of GPST in
///   time_t form, then a double fraction), one record per write: the host's millisecond tick since
///   the open (uint32) and the file position after the write (uint32, or uint64 when the stream
///   was opened with ::P=8; told apart by the record size). Each line gets the time of the first
///   write that holds its end; the median of (that time − sensor tick) is the tick's offset. The
///   first line may be a fragment (logging started mid-line) and so may an unterminated last
///   line: both are skipped and said so.
/// - A run's MCU capture (captures/ttyIMU.cap, frame protocol v1): the IMU_SAMPLE point samples
///   decoded by ReadCaptureImu, on GPS time, FLU, each held until the next.
/// Bad input throws std::runtime_error naming the file, the line (or record) and the field.

#include <string>

#include "hil/harness/characterize/imu_series.h"

namespace hil::harness {

/// The g the CSV's accelerations are given in: standard gravity (the sensor's unit).
inline constexpr double kCsvG_mps2 = 9.80665;

ImuSeries ReadKfginsImuText(const std::string& path);
ImuSeries ReadCsvTimetag(const std::string& csv_path, const std::string& tag_path);
ImuSeries ReadCaptureImuSeries(const std::string& cap_path);

/// `format` auto: `*.cap` is a capture, a file with `PATH.tag` beside it an IMU CSV, anything
/// else KF-GINS text; or kfgins, csv-timetag, capture. @throws std::runtime_error.
ImuSeries ReadImuLog(const std::string& path, const std::string& format = "auto");

}  // namespace hil::harness

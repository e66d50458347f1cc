#pragma once
/// @file
/// `hil export RUN --format kfgins|gnss-ins-sim DIR`: a run's emulated IMU as the device measured
/// it (decoded from the MCU link's capture, capture_imu.h: increments on the device's own clock
/// mapped through its time pulses), its GNSS fixes (gnss_fixes.csv, the harness's own decoding of
/// the receiver's output) and its truth (truth.csv), in KF-GINS's text formats or in
/// gnss-ins-sim's CSV layout, so other people's filters can run on our data.
///
/// kfgins: IMU.txt, GNSS.txt (7 columns), GNSS-POSVEL.txt (13, with the fix velocity), truth.nav,
///         kf-gins.yaml and kf-gins-posvel.yaml (initial state: the truth at the first IMU epoch;
///         noise from the run's navd.conf).
/// gnss-ins-sim: time.csv, gyro-0.csv (deg/s), accel-0.csv (m/s^2) at the IMU's own times (body
///         FRD, the interval's mean rate and specific force), gps_time.csv, gps-0.csv
///         (lat, lon, alt, vN, vE, vD), ref_time.csv with ref_pos.csv, ref_vel.csv (NED) and
///         ref_att_euler.csv (yaw, pitch, roll) at the truth's own 10 Hz times.
/// A fix's σ is navd's NMEA rule: HDOP × nmea_uere_m / √2 per horizontal axis, twice that
/// vertically; its velocity σ is nmea_velocity_std_mps (twice that vertically; both from the run's
/// navd.conf); an NMEA receiver reports no vertical velocity, so vD is 0 for NMEA runs.

#include <cstdint>
#include <string>

namespace hil::harness {

struct RunExportResult {
  std::uint64_t imu_lines = 0, gnss_lines = 0, truth_lines = 0, bad_frames = 0;
};

/// @throws std::runtime_error naming the file for a missing or unreadable input.
RunExportResult ExportRun(const std::string& run_dir, const std::string& format,
                          const std::string& out_dir);

}  // namespace hil::harness

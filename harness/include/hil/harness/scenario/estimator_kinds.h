#pragma once
/// @file
/// The estimator section's choices as enums, parsed once when the scenario is loaded: how the
/// solutions are read (`output`), which navd filter mode the generated navd.conf asks for
/// (`navd_mode`) and which point of the vehicle the estimate describes (`reference_point`). Each
/// enum's names array holds the scenario-file spelling, in the enum's order.

#include <array>
#include <cstddef>
#include <string_view>

namespace hil::harness {

/// How the estimator's solutions are read (scenario key estimator.output).
enum class EstimatorOutput {
  kJsonStdout,   ///< navd's JSON lines on stdout
  kGpsdJson,     ///< gpsd TPV objects on stdout (e.g. from `gpspipe -w`)
  kNmeaStdout,   ///< GGA/RMC on stdout
  kNmeaPty,      ///< GGA/RMC written into the pty RUN_DIR/ttyNAV
  kN2kCandump,   ///< NMEA 2000 PGN 129029 as candump -L lines on stdout
  kN2kSocketcan  ///< navd's NMEA 2000 frames read back from the scenario's CAN bus
};
inline constexpr std::array<std::string_view, 6> kEstimatorOutputNames{
    "json_stdout", "gpsd_json", "nmea_stdout", "nmea_pty", "n2k_candump", "n2k_socketcan"};

/// navd's filter mode (scenario key estimator.navd_mode, navd.conf [filter] mode).
/// kUwb: navd's UWB mode (paper 003), selected by the generated navd.conf's [uwb] section.
enum class NavdMode { kGnssOnly, kEkf, kPlanar2d, kImuOnly, kMultiGnss, kUwb, kGyroOdometry };
inline constexpr std::array<std::string_view, 7> kNavdModeNames{
    "gnss_only", "ekf", "planar2d", "imu_only", "multi_gnss", "uwb", "gyro_odometry"};

/// The point of the vehicle the estimate describes (scenario key estimator.reference_point).
enum class ReferencePoint {
  kAuto,     ///< antenna for a GNSS-only navd, the IMU for navd fusing the board, else the body
  kBody,     ///< the body reference point
  kAntenna,  ///< the antenna of the receiver navd reads (navd_gnss_source.h)
  kImu       ///< the IMU board
};
inline constexpr std::array<std::string_view, 4> kReferencePointNames{"auto", "body", "antenna",
                                                                      "imu"};

/// The scenario-file spelling of a choice.
constexpr std::string_view Name(EstimatorOutput v) {
  return kEstimatorOutputNames[static_cast<std::size_t>(v)];
}
constexpr std::string_view Name(NavdMode v) { return kNavdModeNames[static_cast<std::size_t>(v)]; }
constexpr std::string_view Name(ReferencePoint v) {
  return kReferencePointNames[static_cast<std::size_t>(v)];
}

}  // namespace hil::harness

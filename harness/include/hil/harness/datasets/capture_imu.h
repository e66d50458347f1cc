#pragma once
/// @file
/// The IMU as the device measured it, from a run's capture of the MCU link (frame protocol v1,
/// vectors/mcu/mcu_frame_protocol.md), decoded here independently of navd: every IMU_SAMPLE's
/// rates (STATUS scales, FLU), stamped by the device's own tick, mapped onto GPS time through
/// the latched TIME_PULSE frames (linear between the pulses around a sample; after the last one
/// with the last measured tick rate), and turned into increments over the interval from the
/// previous sample (trapezoidal, as the device's samples are point samples). Frames that fail
/// the CRC are counted and skipped; an MCU reset restarts the increments.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

struct CaptureImuSample {
  double t_gps_s = 0;  ///< GPS seconds since the GPS epoch at the end of the interval
  double dt_s = 0;
  Eigen::Vector3d dtheta_flu_rad = Eigen::Vector3d::Zero();
  Eigen::Vector3d dvel_flu_mps = Eigen::Vector3d::Zero();
};

/// One IMU_SAMPLE as the device sent it (a point sample at its tick), on GPS time.
struct CaptureImuPoint {
  double t_gps_s = 0;
  Eigen::Vector3d w_flu_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_flu_mps2 = Eigen::Vector3d::Zero();
};

struct CaptureImu {
  std::vector<CaptureImuSample> samples;
  /// the samples themselves (every one with a GPS time, reset segments one after the other), for
  /// analyses that must not see the trapezoidal increments' smoothing (hil characterize)
  std::vector<CaptureImuPoint> points;
  std::uint64_t frames = 0, bad_frames = 0, pulses = 0, resets = 0, before_first_pulse = 0;
  /// GPS seconds since the epoch of emulated time 0 (from the first pulse, whose edge lies on a
  /// whole second of both clocks)
  double gps_at_emulated_zero_s = 0;
};

/// @throws std::runtime_error for an unreadable capture or one without time pulses.
CaptureImu ReadCaptureImu(const std::string& capture_path);

}  // namespace hil::harness

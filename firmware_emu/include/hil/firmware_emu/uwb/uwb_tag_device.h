#pragma once
/// @file
/// @system
/// name: UwbTagDevice (paper 003's UWB tag: a Nooploop LinkTrack tag among four anchors BS1–BS4)
/// input: TruthSample at each fix; host bytes (Setting_Frame0 read requests)
/// output: serial port 0 — NLink_LinkTrack_Tag_Frame0 (128 bytes) and/or HIL-UWB-TDOA0 (24 bytes)
///         per fix; a Setting_Frame0 with the anchors in answer to a read request
/// rate: 1–50 Hz (paper 003 §B.3; its tests sample at 5 Hz)
/// @endsystem
/// Frames: the planar frame W of the anchors is the scenario's ENU frame N (east, north); heights
/// are above the ground. The tag sits `tag_height_m` above the body origin (paper 003: the
/// rear-axle centre, 1.6 m). Positions carry UwbErrorModel's errors; the Tag_Frame0 distances and
/// the TDOA differences are the geometric ranges of the measured position (so that a TDOA solve
/// reproduces the module's position), plus the NLOS bias of a blocked anchor, which also moves the
/// position by the linearised TDOA solution's response to it. Every random draw derives from the
/// seed.

#include <array>
#include <cstdint>
#include <string>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/uwb/uwb_error_model.h"

namespace hil::uwb {

enum class UwbOutput : std::uint8_t { kTagFrame0, kTdoa, kBoth };

struct UwbTagConfig {
  std::string name = "uwb";
  int baud = 921600;     ///< Nooploop's ROS launch default
  double rate_hz = 5.0;  ///< paper 003's sampling frequency
  UwbOutput output = UwbOutput::kTagFrame0;
  std::uint8_t tag_id = 0;
  /// BS1–BS4 in W (m). Paper 003 prints no coordinates: a 20 m square around its 15 m field.
  std::array<Eigen::Vector2d, 4> p_W_anchor_m{Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, -10),
                                              Eigen::Vector2d(10, 10), Eigen::Vector2d(-10, 10)};
  double anchor_height_m = 1.6, tag_height_m = 1.6;
  Duration output_lag = std::chrono::milliseconds(5);  ///< fix epoch to first byte
  Duration reply_latency =
      std::chrono::milliseconds(2);  ///< host request to the Setting_Frame0 reply
  double voltage_v = 4.9;
  UwbErrorConfig errors;
};

struct UwbTagStats {
  std::uint64_t fixes = 0, nlos_fixes = 0, setting_replies = 0, host_garbage_bytes = 0;
};

/// What one fix measured, before encoding (for tests and decoders' judges).
struct UwbFix {
  Eigen::Vector2d p_W_true_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d p_W_measured_m = Eigen::Vector2d::Zero();  ///< what the frames carry
  std::array<double, 4> range_m{};                           ///< to BS1–BS4, NLOS included
  std::array<double, 3> r_i1_m{};                            ///< r_21, r_31, r_41
  NlosState nlos;
};

class UwbTagDevice final : public Device {
 public:
  /// @throws std::invalid_argument for a rate outside 1–50 Hz or collinear BS1–BS3.
  UwbTagDevice(const UwbTagConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_fix_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int) const override { return config_.baud; }

  const UwbTagStats& stats() const { return stats_; }
  const UwbFix& last_fix() const { return fix_; }
  const UwbTagConfig& config() const { return config_; }

 private:
  Eigen::Vector2d NlosShift(const Eigen::Vector2d& p_W_m, const NlosState& nlos) const;
  void Emit(Time t, DeviceOutput& out);
  UwbTagConfig config_;
  UwbErrorModel errors_;
  Time next_fix_{};
  Eigen::Vector2d last_p_m_ = Eigen::Vector2d::Zero();
  bool have_last_ = false;
  std::string host_buf_;
  UwbTagStats stats_;
  UwbFix fix_;
};

}  // namespace hil::uwb

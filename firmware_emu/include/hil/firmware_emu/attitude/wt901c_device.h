#pragma once
/// @file
/// @system
/// name: Wt901cDevice (paper 003's WitMotion WT901C attitude sensor, TTL/RS-232 "WIT standard")
/// input: TruthSample at each output cycle; host configuration commands `FF AA REG DATAL DATAH`
/// output: serial port 0 — 11-byte packets 0x51 acceleration, 0x52 angular rate, 0x53 angle,
///         0x54 magnetic field (as enabled by RSW), 0x5F register-read replies
/// rate: RRATE (default 10 Hz), lowered automatically to what the baud rate carries
/// @endsystem
/// Frames: the sensor frame is the body frame B (FLU: x forward, y left, z up; the WT901C's own
/// axis labels are UNVERIFIED). Angles are Z-Y-X Euler of q_NB: yaw counter-clockwise from ENU
/// east, wrapped into [−180°, 180°). Register semantics: vectors/wt901c/README.md. Every random
/// draw derives from the seed given at construction.

#include <array>
#include <cstdint>
#include <string>

#include "hil/firmware_emu/attitude/wt901c_config.h"
#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/mcu/rng.h"

namespace hil::wit {

/// The continuous values (truth plus errors, before quantisation) of the last output cycle: what a
/// decoder must read back within one LSB.
struct Wt901cCycle {
  Eigen::Vector3d accel_g = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate_dps = Eigen::Vector3d::Zero();
  Eigen::Vector3d angle_deg = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw before wrapping
  Eigen::Vector3d mag_counts = Eigen::Vector3d::Zero();
};

struct Wt901cStats {
  std::uint64_t cycles = 0, packets = 0, commands = 0, writes_rejected_locked = 0, read_replies = 0,
                host_garbage_bytes = 0, saves = 0, reboots = 0;
};

class Wt901cDevice final : public Device {
 public:
  static constexpr std::size_t kRegisterCount = 0x70;
  /// @throws std::invalid_argument on an unknown RRATE or BAUD code.
  Wt901cDevice(const Wt901cConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_cycle_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int) const override { return BaudOfCode(reg(kBaud)); }

  /// The current output rate after automatic reduction (Hz; 0 when stopped).
  double effective_rate_hz() const;
  std::uint16_t reg(std::size_t address) const { return regs_[address]; }
  const Wt901cStats& stats() const { return stats_; }
  const Wt901cCycle& last_cycle() const { return cycle_; }
  /// Gyro turn-on bias drawn at power-on (°/s, sensor axes).
  const Eigen::Vector3d& gyro_bias_dps() const { return gyro_bias_dps_; }

  // Register addresses used by the firmware model.
  static constexpr std::size_t kSave = 0x00, kCalsw = 0x01, kRsw = 0x02, kRrate = 0x03,
                               kBaud = 0x04, kReadAddr = 0x27, kVersion = 0x2E, kAx = 0x34,
                               kGx = 0x37, kHx = 0x3A, kRoll = 0x3D, kTemp = 0x40, kKey = 0x69;

 private:
  void LoadDefaults();
  void PowerOn(Time t);
  void Schedule(Time from);
  void HandleCommand(Time t, std::uint8_t reg, std::uint16_t value, DeviceOutput& out);
  void SendPacket(Time t, std::uint8_t type, const std::array<std::int16_t, 4>& d,
                  DeviceOutput& out);
  std::array<std::int16_t, 4> AnglesRaw(const TruthSample& truth);
  static std::array<std::int16_t, 4> Quantise(const Eigen::Vector3d& v, double full_scale,
                                              std::int16_t d3);

  Wt901cConfig config_;
  mcu::Rng rng_;
  std::array<std::uint16_t, kRegisterCount> regs_{}, flash_{};
  Eigen::Vector3d gyro_bias_dps_ = Eigen::Vector3d::Zero();
  double yaw_drift_dps_ = 0, yaw_offset_deg_ = 0, last_yaw_deg_ = 0;
  Time power_on_{}, next_cycle_{}, unlocked_until_{};
  bool single_pending_ = false;
  std::string host_buf_;
  Wt901cStats stats_;
  Wt901cCycle cycle_;
};

}  // namespace hil::wit

#pragma once
/// @file
/// @system
/// name: McuDevice (the IMU board's microcontroller of seed 000, and its graded variants)
/// input: TruthSample at each event (IMU sample, compass sample, GPS time pulse, boot, reset)
/// output: serial port 0 — binary frames (vectors/mcu/mcu_frame_protocol.md) or Razor text lines;
///         CAN — J1939 ARI/ACCS/SSI2 and HIL_TIME_PULSE (vectors/can/README.md)
/// rate: IMU samples at `imu_rate_hz` of the MCU's own clock; compass at its own rate; PPS 1 Hz
/// @endsystem
/// Time: the MCU's free-running 1 MHz tick runs `crystal_ppm` fast; its sample timer fires every
/// round(1e6 / imu_rate_hz) ticks, so in true (scenario) time the samples come every
/// period / (1 + ppm·1e-6), plus interrupt jitter. next_event_time() is in true time; frames carry
/// the tick. The GPS time pulse occurs at each whole GPS second of true time; the MCU latches its
/// tick there. Every random draw derives from the seed given at construction.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/mcu/imu_front_end.h"
#include "hil/firmware_emu/mcu/mcu_config.h"
#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/mcu/sensor_triad.h"

namespace hil::mcu {

/// Counters of what the device did (for tests and reports).
struct McuStats {
  std::uint64_t imu_samples = 0, mag_samples = 0, time_pulses = 0, status_frames = 0;
  std::uint64_t frames_dropped = 0, frames_corrupted = 0, resets = 0, can_frames = 0;
};

class McuDevice final : public Device {
 public:
  /// @throws std::invalid_argument on an inconsistent configuration (non-positive rates, …).
  McuDevice(const McuConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override;
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  int baud(int) const override { return config_.baud; }

  const McuStats& stats() const { return stats_; }
  DeviceStatistics statistics() const override { return {stats_.resets}; }
  /// Actual tick rate (Hz) of the MCU's crystal.
  double tick_hz() const { return tick_hz_; }
  /// The tick the MCU's counter shows at true time t (wraps at 2³²).
  std::uint32_t TickAt(Time t) const;
  /// Nominal IMU sample period in ticks.
  std::uint32_t imu_period_ticks() const { return imu_period_ticks_; }

 private:
  void Boot(Time t_boot);
  void ScheduleImu();
  void OnImuSample(const TruthSample& truth, DeviceOutput& out);
  /// Frames of one IMU sample, tagged (tick) and sent at `t_tag`.
  void EmitImu(Time t_tag, const TriadCounts& a, const TriadCounts& g, std::uint64_t index,
               DeviceOutput& out);
  double TemperatureAt(double t_s) const;
  void OnMagSample(const TruthSample& truth);
  void OnTimePulse(Time t, DeviceOutput& out);
  void SendStatus(Time t, DeviceOutput& out);
  void SendSerial(Time t_sample, std::string bytes, const char* what, DeviceOutput& out);
  bool Stuck(const char* sensor, Time t) const;
  std::uint16_t NextSequence(Time t);
  bool ActiveFault(FaultKind kind, Time t, const McuFault** which) const;

  McuConfig config_;
  Rng timing_rng_, fault_rng_;
  SensorTriad accel_, gyro_, mag_;
  double tick_hz_;
  std::uint32_t imu_period_ticks_;
  Duration mag_period_;

  // state
  bool up_ = true;
  Time boot_{};  ///< true time of tick 0
  std::optional<Time> pending_status_;
  std::optional<Time> pending_boot_;
  std::uint64_t imu_index_ = 0;
  Time next_imu_{}, next_mag_{}, next_pps_{};
  std::vector<std::pair<Time, Duration>> resets_;  ///< pending resets: time, silent gap (ascending)
  std::vector<bool> jump_applied_;
  std::uint16_t sequence_ = 0;
  std::uint16_t reset_count_ = 0;
  std::uint8_t reset_cause_ = 0;
  std::optional<Time> last_pulse_;
  TriadCounts last_accel_{}, last_gyro_{}, last_mag_{};
  bool have_accel_ = false, have_gyro_ = false, have_mag_ = false;
  McuStats stats_;
  // issue 41: the vibration front end and the time tag of samples sensed earlier than tagged
  std::optional<ImuFrontEnd> front_end_;
  Rng tag_rng_;
  struct PendingImu {
    Time t_tag;
    TriadCounts accel, gyro;
    std::uint64_t index;
  };
  std::deque<PendingImu> pending_imu_;
};

}  // namespace hil::mcu

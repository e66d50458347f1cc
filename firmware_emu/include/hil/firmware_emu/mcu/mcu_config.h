#pragma once
/// @file
/// Configuration of the emulated IMU-board microcontroller (immutable after construction): its
/// sensors, clock, sampling, serial format, CAN output and firmware faults. The harness fills it
/// from the scenario's `mcu:` section (harness/src/scenario/scenario_mcu.cc).

#include <cstdint>
#include <string>
#include <vector>

#include "hil/firmware_emu/mcu/imu_kinematics.h"
#include "hil/firmware_emu/mcu/j1939_imu.h"
#include "hil/firmware_emu/mcu/rough_imu_spec.h"
#include "hil/firmware_emu/mcu/sensor_spec.h"
#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/unix_time.h"

namespace hil::mcu {

/// What the MCU writes to its UART.
enum class SerialFormat {
  kBinary,    ///< the project's frame protocol (vectors/mcu/mcu_frame_protocol.md)
  kRazorRaw,  ///< stock Razor text `$,…,#`
  kRazorV19,  ///< stock Razor v19 text `!Data:…#`
};

enum class FaultKind {
  kDropFrames,    ///< frames queued but lost with `probability` during [start, start + duration)
  kSequenceJump,  ///< at `start`, the sequence counter advances by `amount` extra
  kCorruptBytes,  ///< with `probability` per frame, one byte is flipped (the CRC then fails)
  kStuckSensor,   ///< `sensor` repeats its last counts during [start, start + duration)
  kReset,         ///< at `start` the MCU resets: silent for `duration` (when > 0; else the config's
                  ///< `reboot`, YAML `reboot_s`), then tick and sequence restart
};

/// One entry of the firmware fault timeline.
struct McuFault {
  FaultKind kind = FaultKind::kDropFrames;
  Time start{};  ///< emulated time
  Duration duration{0};
  double probability = 1.0;
  int amount = 1;              ///< sequence jump size
  std::string sensor = "all";  ///< accel | gyro | mag | all (stuck sensor)
};

/// The J1939 output.
struct CanOutputConfig {
  bool enabled = false;
  J1939Address address;
  int ari_every = 1;  ///< one ARI per this many IMU samples
  int accs_every = 1;
  int ssi2_every = 1;
  bool time_pulse = true;    ///< HIL_TIME_PULSE once per GPS time pulse
  double latency_s = 0.001;  ///< sample instant to frame on the bus
};

struct McuConfig {
  std::string name = "mcu";
  ImuProfile profile = ProfileByName("razor-v13");
  int baud = 57600;
  SerialFormat format = SerialFormat::kBinary;
  double imu_rate_hz = 10;  ///< default: 10 × the GPS rate of seed 000
  double mag_rate_hz = 10;
  double crystal_ppm = 0;         ///< MCU tick rate offset from nominal 1 MHz
  double mag_oscillator_ppm = 0;  ///< compass output-rate oscillator offset
  double jitter_us = 0;           ///< interrupt latency of a sample, uniform in [0, jitter]
  Duration first_sample_delay = std::chrono::milliseconds(10);  ///< boot to first IMU sample
  Duration output_lag = std::chrono::microseconds(500);  ///< sample to frame ready for the UART
  Duration reboot = std::chrono::milliseconds(200);      ///< reset to boot
  UnixTime start_utc{};    ///< UTC of scenario time 0 (for the GPS time pulse)
  bool time_pulse = true;  ///< the receiver's PPS is wired to the MCU
  BoardMounting mounting;
  MagneticSpec magnetic;
  std::vector<VibrationTone> vibration;
  double temperature_c = 25;            ///< board temperature at t = 0
  double temperature_rate_c_per_h = 0;  ///< linear warm-up
  /// Issue 41's field-rough model: vibration front end, temperature profile, time tag (off by
  /// default; field_profiles.h names calibrated sets).
  RoughImuSpec rough;
  CanOutputConfig can;
  std::vector<McuFault> faults;
};

}  // namespace hil::mcu

#pragma once
/// @file
/// @system
/// name: TfLunaDevice (paper 001's laser rangefinders: Benewake TF-Luna / TFmini-S on a UART)
/// input: TruthSample at each output frame (2-D pose), the greenhouse map to cast the beam
///        against; host commands `5A LEN ID payload CS`
/// output: serial port 0 — 9-byte data frames `59 59 …` (cm or mm) or PIX text lines, and
///         command replies
/// rate: 500/n Hz (default 100 Hz); rate 0 = trigger mode
/// @endsystem
/// One module per device (paper 001 has four: right-front, right-rear, left-front, left-rear).
/// The beam is a ray from the mount point in the body frame B (FLU) at `mount.z_m` above a flat
/// floor, along `mount.yaw_deg` (counter-clockwise from forward: −90 looks right); roll and
/// pitch are ignored (UNVERIFIED simplification for a level greenhouse floor). Command handling
/// and reply formats: vectors/rangefinder/README.md. Every random draw derives from the seed.

#include <cstdint>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/rangefinder/benewake_framing.h"
#include "hil/firmware_emu/rangefinder/tf_luna_model.h"
#include "hil/firmware_emu/world/greenhouse_world.h"

namespace hil::rangefinder {

struct RangefinderMount {
  double x_m = 0, y_m = 0, z_m = 0.15;  ///< in B (FLU), z above the floor
  double yaw_deg = -90;                 ///< beam direction, counter-clockwise from forward
};

/// The settings a module keeps in flash (saved with 0x11, restored with 0x10).
struct TfLunaSettings {
  std::uint16_t frame_rate_hz = 100;
  OutputFormat format = OutputFormat::kCm9Byte;
  std::uint32_t baud = 115200;
  bool output_enabled = true;
};

struct TfLunaConfig {
  std::string name = "rf_right_front";
  RangefinderMount mount;
  RangeModelConfig model;
  world::SurfaceReflectivity reflectivity;
  TfLunaSettings settings;  ///< factory defaults (the manual's)
  double chip_temperature_c = 40;
  double cast_range_m = 12;  ///< how far the beam is traced (beyond the 9 m limit)
  Duration reply_latency = std::chrono::milliseconds(1);  ///< command → reply (UNVERIFIED)
  Duration boot_time = std::chrono::seconds(1);  ///< reset → first frame (TF02-Pro note: wait 1 s)
  std::array<std::uint8_t, 3> firmware_version{3, 0, 1};  ///< major, minor, patch (UNVERIFIED)
};

struct TfLunaStats {
  std::uint64_t frames = 0, invalid_frames = 0, commands = 0, replies = 0, unsupported = 0,
                resets = 0, saves = 0;
};

class TfLunaDevice final : public Device {
 public:
  /// `world` must outlive the device. @throws std::invalid_argument on a frame rate above 250
  /// Hz or an unsupported baud.
  TfLunaDevice(const TfLunaConfig& config, const world::GreenhouseWorld& world, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_frame_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int) const override { return static_cast<int>(settings_.baud); }
  DeviceStatistics statistics() const override { return {stats_.resets}; }

  /// The effective output rate (Hz; 0 in trigger mode or when output is disabled).
  double effective_rate_hz() const;
  const TfLunaSettings& settings() const { return settings_; }
  const TfLunaStats& stats() const { return stats_; }
  const CommandReaderStats& command_stats() const { return reader_.stats(); }
  /// The last reading sent, with its continuous value and the true range behind it.
  const Reading& last_reading() const { return reading_; }
  const Target& last_target() const { return target_; }

 private:
  Target Sense(const TruthSample& truth) const;
  void SendFrame(const TruthSample& truth, DeviceOutput& out);
  void Handle(const CommandFrame& f, DeviceOutput& out);  // tf_luna_commands.cc
  void HandleSetting(const CommandFrame& f, DeviceOutput& out);
  void Reply(std::string bytes, DeviceOutput& out);
  void Schedule(Time from);

  TfLunaConfig config_;
  const world::GreenhouseWorld* world_;
  mcu::Rng rng_;
  TfLunaSettings settings_, flash_;
  CommandReader reader_;
  std::vector<CommandFrame> pending_;
  Time now_{}, next_frame_{};
  bool trigger_pending_ = false;
  Reading reading_;
  Target target_;
  TfLunaStats stats_;
};

}  // namespace hil::rangefinder

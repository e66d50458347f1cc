#pragma once
/// @file
/// @system
/// name: RplidarDevice (paper 001's 2-D LiDAR: a Slamtec RPLIDAR A1M8 / A2M8 on a UART)
/// input: TruthSample at each batch of samples (2-D pose, velocity, yaw rate), the greenhouse map
///        to cast each beam against; host requests `A5 CMD [SIZE PAYLOAD CS]`
/// output: serial port 0 — response descriptors, GET_INFO / GET_HEALTH / GET_SAMPLERATE /
///         GET_ACC_BOARD_FLAG data, SCAN nodes (5 bytes), EXPRESS_SCAN legacy capsules (84
///         bytes), the text banner after RESET
/// rate: rotation `rotation_hz` (A1 typical 5.5 Hz), 1e6/standard_sample_us samples/s in SCAN,
///       1e6/express_sample_us in EXPRESS_SCAN
/// @endsystem
/// Frames: the LiDAR's angle θ runs clockwise from its forward axis (protocol), which points along
/// `mount.yaw_deg` in the body frame B (FLU); the beam's direction in B is mount.yaw − θ. The
/// scan plane is horizontal at `mount.z_m` above a flat floor: ridges lower than that are not
/// seen. Each sample is cast at its own time: the pose of the batch's truth sample is moved back
/// along its velocity and yaw rate. Session details: vectors/rplidar/README.md.

#include <cstdint>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/lidar/rplidar_request.h"
#include "hil/firmware_emu/lidar/rplidar_response.h"
#include "hil/firmware_emu/mcu/rng.h"
#include "hil/firmware_emu/world/greenhouse_world.h"

namespace hil::lidar {

enum class RplidarModel { kA1M8, kA2M8 };

struct LidarMount {
  double x_m = 0, y_m = 0, z_m = 0.4, yaw_deg = 0;
};

struct RplidarConfig {
  std::string name = "lidar";
  RplidarModel model = RplidarModel::kA1M8;
  LidarMount mount;
  double rotation_hz = 5.5;
  std::uint16_t standard_sample_us = 500;         ///< 2000 samples/s (A1; A2 in the legacy SCAN)
  std::uint16_t express_sample_us = 250;          ///< 4000 samples/s
  double min_range_m = 0.15, max_range_m = 12.0;  ///< A1 datasheet range (UNVERIFIED)
  /// σ of the distance as a fraction of the range: half the datasheet's 1 % accuracy (UNVERIFIED).
  double range_sigma_fraction = 0.005;
  double white_range_m = 12.0;  ///< farthest return on a 90 % white target facing the beam
  world::SurfaceReflectivity reflectivity;
  /// motor start → stable rotation (no samples before, UNVERIFIED)
  Duration spin_up = std::chrono::milliseconds(500);
  Duration reply_latency = std::chrono::milliseconds(1);
  Duration banner_delay = std::chrono::milliseconds(10);  ///< RESET → banner (UNVERIFIED)
  std::size_t nodes_per_message = 20;  ///< SCAN nodes handed to the UART together (10 ms at 2 kHz)
  int baud = 115200;
  DeviceInfo info;  ///< serial number drawn from the seed when all zero
};

/// One sample with its continuous truth (for golden expectations and tests).
struct LidarSample {
  Time t{};
  double angle_deg = 0;     ///< θ, clockwise from the LiDAR's forward axis, [0, 360)
  double true_range_m = 0;  ///< 0: nothing within the cast range
  double measured_m = 0;    ///< 0: no return
  std::uint8_t quality = 0;
  bool start = false;
};

struct RplidarStats {
  std::uint64_t requests = 0, ignored = 0, nodes = 0, capsules = 0, resets = 0;
};

class RplidarDevice final : public Device {
 public:
  /// `world` must outlive the device.
  RplidarDevice(const RplidarConfig& config, const world::GreenhouseWorld& world,
                std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_event_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int) const override { return config_.baud; }
  DeviceStatistics statistics() const override { return {stats_.resets}; }

  /// The samples of the last event (a node batch or one capsule).
  const std::vector<LidarSample>& last_samples() const { return samples_; }
  const RplidarStats& stats() const { return stats_; }
  const RequestReaderStats& request_stats() const { return reader_.stats(); }
  bool motor_on() const { return motor_on_; }
  /// The banner text RESET prints (model and firmware from the configuration).
  std::string Banner() const;

 private:
  enum class Mode { kIdle, kScan, kExpress };
  void Handle(const RequestFrame& r, DeviceOutput& out);  // rplidar_session.cc
  void Send(std::string bytes, const char* what, DeviceOutput& out);
  void StartScan(Mode mode, bool force);
  void StartMotor(Time t);
  double AngleAt_deg(Time t) const;
  LidarSample Sample(const TruthSample& truth, Time t);
  void EmitNodes(const TruthSample& truth, DeviceOutput& out);
  void EmitCapsule(const TruthSample& truth, DeviceOutput& out);
  Duration SamplePeriod() const;
  std::size_t SamplesPerEvent() const;

  RplidarConfig config_;
  const world::GreenhouseWorld* world_;
  mcu::Rng rng_;
  RequestReader reader_;
  std::vector<RequestFrame> pending_;
  Mode mode_ = Mode::kIdle;
  bool motor_on_ = true, capsule_new_scan_ = false;
  Time now_{}, motor_t0_{}, scan_t0_{}, next_event_{};
  std::uint64_t sample_index_ = 0;
  double last_angle_deg_ = 0;
  std::vector<LidarSample> samples_;
  RplidarStats stats_;
};

}  // namespace hil::lidar

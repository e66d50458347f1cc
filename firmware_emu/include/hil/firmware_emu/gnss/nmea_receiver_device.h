#pragma once
/// @file
/// @system
/// name: NmeaReceiverDevice (a standalone GNSS receiver that outputs NMEA only)
/// input: TruthSample at each navigation epoch
/// output: RMC then GGA per epoch, ready `output_lag` after the epoch, on serial port 0
/// rate: the navigation rate
/// @endsystem
/// The minimal receiver of the foundation; the full NEO-5M (UBX, CFG, all NMEA sentences) builds
/// on the same ReceiverModel.

#include <cstdint>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/receiver_model.h"

namespace hil::gnss {

struct NmeaReceiverConfig {
  std::string name = "gps0";
  int baud = 9600;
  double rate_hz = 1.0;
  Duration output_lag = std::chrono::milliseconds(100);
  std::int64_t start_unix_ns = 0;  ///< UTC of scenario time 0
  ReceiverModelConfig model;
};

class NmeaReceiverDevice final : public Device {
 public:
  NmeaReceiverDevice(const NmeaReceiverConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_epoch_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  int baud(int) const override { return config_.baud; }
  /// The last fix produced (the raw GNSS baseline reads it).
  const GnssFix& last_fix() const { return last_fix_; }

 private:
  NmeaReceiverConfig config_;
  ReceiverModel model_;
  Time next_epoch_{};
  Time last_epoch_{};
  bool first_ = true;
  GnssFix last_fix_;
};

}  // namespace hil::gnss

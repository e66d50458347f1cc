#pragma once
/// @file
/// A capture played back as a device: the engine drives it like an emulated device, so a
/// replay has the run's one clock (engine/engine.h). At each recorded time it hands over what was
/// recorded then: serial chunks as messages timed already (byte k at t_emu_ns + k·byte_period_ns,
/// as recorded, not through a UART model) on the port of their link, and CAN frames as they were
/// on the wire. It reads no truth and answers no host.

#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/harness/links/capture_format.h"

namespace hil::harness {

/// One recorded thing to play: a serial chunk (`port` ≥ 0) or a CAN frame (`port` < 0).
struct ReplayItem {
  Time t{};
  int port = -1;
  CaptureRecord record;
};

class ReplayDevice final : public Device {
 public:
  /// `items` in any order (played in time order; equal times keep their order); `bauds[p]` is
  /// the recorded line rate of serial port p.
  ReplayDevice(std::vector<ReplayItem> items, std::vector<int> bauds);
  const std::string& name() const override { return name_; }
  /// The next recorded time; Time::max() when everything has been handed over.
  Time next_event_time() const override;
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  int baud(int port) const override { return bauds_.at(static_cast<std::size_t>(port)); }
  int serial_port_count() const override { return static_cast<int>(bauds_.size()); }

 private:
  std::string name_ = "replay";
  std::vector<ReplayItem> items_;
  std::vector<int> bauds_;
  std::size_t next_ = 0;
};

}  // namespace hil::harness

#pragma once
/// @file
/// The front-steered vehicle's steering ECU as a device of the scheduler (closed loop, ISOBUS
/// channel; vectors/isobus/README.md): the emulated ECU (steering_ecu.h) receives Guidance System
/// Command frames, steers the road wheels, and answers Guidance Machine Info and Wheel-based Speed
/// and Distance every 100 ms. The road-wheel angle drives the truth's kinematic bicycle model
/// (κ = tan δ / L) at the vehicle's set speed (the operator's hand throttle: ISO 11783-7 guidance
/// steers only).
///
/// Two transports carry the same ISOBUS frames:
///  - `kSocketCan`: the run's CAN bus (vcan0 in the VM, a real can0): the ECU's frames leave
///    through DeviceOutput::can, the controller's arrive through OnBusFrame;
///  - `kSlcan`: a serial CAN adapter on a pty speaking SLCAN (slcan_adapter.h), for hosts without
///    CAN sockets: the controller (or `slcand`) opens the channel and the frames travel as ASCII
///    records on serial port 0.
///
/// Events lie on the truth's command grid (`grid`, 10 ms): at each the ECU advances with the
/// truth's speed and hands its road-wheel angle to the truth for the next grid instant. Control
/// ticks (every `control_period`) count a missing command as the differential-drive base does.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/actuator/command_link_loss.h"
#include "hil/firmware_emu/actuator/control_tick_clock.h"
#include "hil/firmware_emu/actuator/steering_ecu.h"
#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/slcan_adapter.h"

namespace hil::actuator {

enum class IsobusTransport : std::uint8_t { kSocketCan, kSlcan };

struct IsobusSteeringDeviceConfig {
  std::string name = "steering_ecu";
  SteeringEcuConfig ecu;
  IsobusTransport transport = IsobusTransport::kSocketCan;
  int slcan_baud = 115200;  ///< the adapter's serial line (a CAN232's default)
  double speed_mps = 1.0;   ///< the vehicle's set forward speed
  Duration grid = std::chrono::milliseconds(10);
  Duration control_period = std::chrono::milliseconds(100);
  Duration command_timeout = std::chrono::milliseconds(300);
  Time first_command_due{std::chrono::seconds(3)};
  /// Command-link loss: frames from the controller arriving in [first, second) are lost.
  std::vector<std::pair<Time, Time>> link_loss;
};

/// One control tick's record, for the report.
struct SteeringTickRecord {
  Time t{};
  double commanded_steer_rad = 0;  ///< the ECU's target road-wheel angle (left positive)
  double steer_rad = 0;            ///< the actual one (left positive)
  bool engaged = false;
  bool missing = false;
};

/// last_command: arrival of the latest valid Guidance System Command.
struct IsobusSteeringCounters : ControlTickCounters {
  std::uint64_t frames_from_controller = 0;
};

class IsobusSteeringDevice : public Device {
 public:
  explicit IsobusSteeringDevice(const IsobusSteeringDeviceConfig& config);

  const std::string& name() const override { return cfg_.name; }
  Time next_event_time() const override { return tick_.next_event_time(); }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  void OnBusFrame(Time t, const CanFrame& frame, DeviceOutput& out) override;
  int baud(int port) const override;
  int serial_port_count() const override {
    return cfg_.transport == IsobusTransport::kSlcan ? 1 : 0;
  }
  std::optional<VehicleCommand> TakeVehicleCommand() override;

  const SteeringEcu& ecu() const { return ecu_; }
  const link::SlcanAdapter& adapter() const { return adapter_; }
  const IsobusSteeringCounters& counters() const { return counters_; }
  /// Controller frames lost to the command-link loss windows.
  const CommandLinkLoss& link_loss() const { return loss_; }
  /// Control ticks while engaged, and the sum over them of (actual − commanded road-wheel
  /// angle)² in rad², in tick order (none kept: a run's length does not grow the device).
  std::uint64_t engaged_ticks() const { return engaged_ticks_; }
  double engaged_steer_error_sq_sum_rad2() const { return engaged_error_sq_sum_rad2_; }
  /// Each control tick's record goes to `tap` as it is made (the report's steering chart).
  void set_tick_tap(std::function<void(const SteeringTickRecord&)> tap) {
    tick_tap_ = std::move(tap);
  }

 private:
  void FromController(Time t, const CanFrame& frame);
  void ControlTick(Time t);
  /// The ECU's status frames onto the transport.
  void Send(DeviceOutput& ecu_out, DeviceOutput& out);

  IsobusSteeringDeviceConfig cfg_;
  SteeringEcu ecu_;
  link::SlcanAdapter adapter_;
  ControlTickClock tick_;
  double distance_m_ = 0;
  std::uint64_t seen_accepted_ = 0;
  IsobusSteeringCounters counters_;
  CommandLinkLoss loss_;
  std::uint64_t engaged_ticks_ = 0;
  double engaged_error_sq_sum_rad2_ = 0;
  DeviceOutput scratch_;
  std::vector<CanFrame> host_frames_;
  std::function<void(const SteeringTickRecord&)> tick_tap_ = [](const SteeringTickRecord&) {};
};

}  // namespace hil::actuator

#pragma once
/// @file
/// The interface between the scheduler (harness) and every emulated device.
///
/// A device is an event source driven by one scheduler that owns the clock (see
/// harness/include/hil/harness/run/run.h for the order of operations at each event time):
///  - the scheduler asks `next_event_time()`, samples the truth there and calls `OnEvent()`;
///  - the device answers with whole serial messages (each ready at an emulated time; the UART queue
///    of its port turns them into timed bytes, or drops them) and CAN frames;
///  - bytes the host writes to a device's serial port reach it through `OnHostBytes()`, stamped
///    with their emulated arrival time; the device may answer (ACK, polled message) and change its
///    port settings (baud).
/// Devices never touch descriptors or the wall clock: the bytes they produce depend only on the
/// scenario and the seed.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/truth_sample.h"

namespace hil {

/// One whole message for a serial port, ready to enter the UART at `t_ready`.
struct SerialMessage {
  Time t_ready{};
  int port = 0;       ///< the device's serial port index (0 for single-port devices)
  std::string bytes;  ///< the complete framed message
  std::string name;   ///< e.g. "NMEA-GGA", "UBX-NAV-SOL" — for diagnostics and drop counting
  /// Bytes timed already (a replayed capture): byte k starts at t_ready + k·byte_period, as
  /// recorded, instead of going through the port's UART model. Emulated devices leave it unset.
  std::optional<Duration> byte_period{};
  /// An answer to a host command (a polled message, an ACK): it goes on the line ahead of the
  /// device's queued output that has not begun by its t_ready (UartTxQueue::SubmitAhead).
  bool reply = false;
};

/// One CAN frame as the device puts it on the bus at `t`.
struct CanFrame {
  Time t{};
  std::uint32_t id = 0;  ///< 11- or 29-bit identifier (without flags)
  bool extended = true;
  std::uint8_t len = 0;  ///< data length, 0–8 (classic) or up to 64 (FD); RTR: the length asked
  bool fd = false;
  bool rtr = false;           ///< remote transmission request (a replayed frame)
  bool error = false;         ///< error frame (a replayed frame; `id` holds the error class)
  std::uint8_t fd_flags = 0;  ///< CAN FD flags: bit 0 BRS, bit 1 ESI
  std::array<std::uint8_t, 64> data{};
};

/// What a device produced at one event.
struct DeviceOutput {
  std::vector<SerialMessage> serial;
  std::vector<CanFrame> can;
  void clear() {
    serial.clear();
    can.clear();
  }
};

/// What a device counted during a run that the run's report needs (the harness sums them over
/// the devices). A device that counts none of them reports zeros.
struct DeviceStatistics {
  std::uint64_t resets = 0;  ///< resets the device went through (scripted or commanded)
};

/// Closed loop: what an actuator drives the truth vehicle with from the first truth-command grid
/// instant at or after `t` on (TruthIntegrator::SetCommand): forward speed and the steering input
/// (front-wheel angle in rad, left positive, for the bicycle models; yaw rate in rad/s, left
/// positive, for a differential-drive base).
struct VehicleCommand {
  Time t{};
  double speed_mps = 0;
  double steer_or_yaw_rate = 0;
};

/// An emulated device.
class Device {
 public:
  virtual ~Device() = default;
  /// Short name, e.g. "gps0" or "mcu".
  virtual const std::string& name() const = 0;
  /// The next emulated time at which the device needs the truth (monotonic, non-decreasing).
  virtual Time next_event_time() const = 0;
  /// Handles the event at `truth.t == next_event_time()` and appends what it sends to `out`.
  virtual void OnEvent(const TruthSample& truth, DeviceOutput& out) = 0;
  /// Bytes the host wrote to serial port `port`, arriving at emulated time `t`.
  virtual void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
    (void)port, (void)t, (void)bytes, (void)out;
  }
  /// Closed loop: a frame another node (the controller under test) put on the run's CAN bus,
  /// arriving at emulated time `t`; the device may answer. Devices that listen to nothing ignore
  /// it.
  virtual void OnBusFrame(Time t, const CanFrame& frame, DeviceOutput& out) {
    (void)t, (void)frame, (void)out;
  }
  /// Current line rate of serial port `port` in bit/s (configuration may change it).
  virtual int baud(int port) const = 0;
  /// Number of serial ports the device has.
  virtual int serial_port_count() const { return 1; }
  /// The counters of the run so far (DeviceStatistics).
  virtual DeviceStatistics statistics() const { return {}; }
  /// Closed loop: an actuator's new output after its event (at most one per event), which the
  /// scheduler hands to the truth. Devices that drive nothing return nullopt.
  virtual std::optional<VehicleCommand> TakeVehicleCommand() { return std::nullopt; }
};

}  // namespace hil

#pragma once
/// @file
/// The CAN bus of a run, as SerialEndpoint is a serial port: frames the devices put on the bus at
/// their emulated times go out on a raw SocketCAN socket (vcan0 in the VM, a real can0 on a bench),
/// frames others send (the estimator's output) are read back, and both directions are captured:
///  - `captures/<iface>.candump`: a `candump -l` log (time = scenario start UTC + emulated time),
///  so
///    can-utils' canplayer replays it and `hil replay` plays it;
///  - `captures/<iface>.cap`: the hil capture (ftx/frx lines with emulated and wall-clock times).
/// Virtual mode sends every queued frame at once; real-time mode sends each at its wall time and
/// records the schedule error.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/link/socketcan_port.h"
#include "hil/harness/links/capture_format.h"

namespace hil::harness {

class CanEndpoint {
 public:
  /// Opens `iface` and creates both captures in `capture_dir`.
  /// @param start_unix_ns UTC of emulated t = 0 (candump log timestamps)
  /// @throws std::runtime_error when the interface cannot be opened (the message says when the
  ///         kernel has no CAN at all and points at ci/vcan/run_in_vm).
  CanEndpoint(const std::string& iface, const std::string& capture_dir, std::int64_t start_unix_ns,
              bool fd = false);

  /// Queues a device's frame to leave at frame.t (frames of one device come in time order; frames
  /// of several devices are merged by time).
  void Queue(const CanFrame& frame);
  /// Emulated time of the next frame waiting to be sent.
  std::optional<Time> next_frame_time() const;
  /// Sends the next frame at its wall time (real time) and records the schedule error.
  void SendNext(const link::RealtimePacer& pacer);
  /// Sends every queued frame now (virtual mode).
  void SendAll();
  /// Reads every frame waiting on the bus (non-blocking), captures it at emulated time `t_now`
  /// and returns it (time-stamped `t_now`; error frames are counted, not returned).
  std::vector<CanFrame> PollBus(Time t_now);

  const std::string& iface() const { return port_.ifname(); }
  const link::CanPortStats& stats() const { return port_.stats(); }
  /// Schedule errors (µs) of frames sent in real time: wall time sent − scheduled wall time.
  const std::vector<double>& schedule_error_us() const { return schedule_error_us_; }

 private:
  void Capture(CaptureDir dir, Time t, std::int64_t wall_ns, const link::CanWireFrame& f);

  link::SocketCanPort port_;
  std::int64_t start_unix_ns_;
  link::CandumpLogWriter candump_;
  CaptureWriter capture_;
  std::deque<CanFrame> pending_;
  std::vector<double> schedule_error_us_;
};

}  // namespace hil::harness

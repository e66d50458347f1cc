#pragma once
/// @file
/// The CAN bus of a run, as SerialEndpoint is a serial port: frames the devices put on the bus at
/// their emulated times go out on a raw SocketCAN socket (vcan0 in the VM, a real can0 on a bench),
/// frames others send (the estimator's output) are read back, and both directions are captured:
///  - `captures/<iface>.candump`: a `candump -l` log (time = scenario start UTC + emulated time),
///    so can-utils' canplayer replays it and `hil replay` plays it;
///  - `captures/<iface>.cap`: the hil capture (ftx/frx lines with emulated and wall-clock times).
/// Virtual mode sends every queued frame at once and captures it at its emulated time (the same
/// bytes in every run); frames from others get the emulated time they were read at, or, in a
/// closed loop (set_stamp_at_turns), the time of the host turn that hands them to the devices.
/// Real-time mode sends each frame at its wall time and records the schedule error; the captures
/// then say when each frame was on the bus, as candump does: the socket receives its own frames
/// back (CAN_RAW_RECV_OWN_MSGS) and every frame, ours and others', is captured in the order the
/// socket got them, at the kernel's receive time (SO_TIMESTAMPNS) mapped onto emulated time. The
/// captures are therefore in bus order with time never going backwards. A sent frame whose echo
/// never came (the receive queue overflowed) is captured at the time its write returned.
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/link/socketcan_port.h"
#include "hil/firmware_emu/unix_time.h"
#include "hil/harness/core/quantile_sketch.h"
#include "hil/harness/links/bus_tx_counter.h"
#include "hil/harness/links/capture_format.h"

namespace hil::harness {

class CanEndpoint {
 public:
  /// Opens `iface` and creates both captures in `capture_dir`.
  /// @param start_utc UTC of emulated t = 0 (candump log timestamps)
  /// @throws std::runtime_error when the interface cannot be opened (the message says when the
  ///         kernel has no CAN at all and points at ci/vcan/run_in_vm).
  CanEndpoint(const std::string& iface, const std::string& capture_dir, UnixTime start_utc,
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
  /// Reads every frame waiting on the bus (non-blocking) and returns the frames others sent since
  /// the last call (error frames are counted, not returned). `pacer` null (virtual mode): they are
  /// stamped `t_now`; otherwise with the emulated time of their kernel receive time.
  std::vector<CanFrame> PollBus(Time t_now, const link::RealtimePacer* pacer);
  /// Virtual mode's closed loop: frames others send are not stamped when read (that moment
  /// depends on the machine) but by TakeArrivals at the engine's host turns, with the emulated
  /// time the devices take them at; PollBus then returns none of them.
  void set_stamp_at_turns(bool on) { stamp_at_turns_ = on; }
  /// Reads the bus and returns every frame others sent since the last call, stamped `t_arrival`
  /// (error frames are captured, not returned). Their capture records wait until the capture
  /// reaches that time, so the captures stay in time order and say when each frame arrived.
  /// On a vcan interface it first waits, at most kSentFramesWait, until it has read as many frames
  /// as were sent on the interface (bus_tx_counter.h): a host that went idle after a send has its
  /// frame counted there before the frame reaches this socket, so without the wait a frame would
  /// be stamped at this turn or the next depending on the machine's load.
  std::vector<CanFrame> TakeArrivals(Time t_arrival);
  static constexpr Duration kSentFramesWait = std::chrono::seconds(1);
  /// Virtual mode: reads the bus until the echoes of every frame sent have come back, at most
  /// `limit` (then counted in sent_frames_wait_timeouts() and not awaited again). The kernel hands
  /// a frame to every socket on the interface in one pass (the echo to ours among them): a host's
  /// socket then has it, and the host, woken, is no longer asleep until it has read it. Others'
  /// frames read meanwhile wait for TakeArrivals (with set_stamp_at_turns; else `t_now` stamps
  /// them).
  void AwaitEchoes(Time t_now, Duration limit);
  /// Turns at which the frames sent on the interface were not all read within kSentFramesWait
  /// (a receive queue that dropped frames, or a sender on another machine's end), or the echoes
  /// of ours did not all come back (AwaitEchoes).
  std::uint64_t sent_frames_wait_timeouts() const { return sent_frames_wait_timeouts_; }
  /// Real time: waits up to `timeout` for the echoes of the frames sent, reading the bus meanwhile
  /// (PollBus returns what others sent), then captures any frame still without an echo at its
  /// write time. The destructor does the same without waiting, after capturing what the socket
  /// still holds (e.g. the estimator's last frames).
  void FinishCapture(Duration timeout);

  const std::string& iface() const { return port_.ifname(); }
  const link::CanPortStats& stats() const { return port_.stats(); }
  /// Schedule errors (µs) of frames sent in real time: wall time sent − scheduled wall time (a
  /// sketch: exact up to QuantileSketch::kExactLimit frames, within its relative accuracy beyond).
  const QuantileSketch& schedule_error_us() const { return schedule_error_us_; }
  /// Where the capture notes a failed write (CaptureWriter::ReportFailuresTo).
  void ReportWriteFailuresTo(RunDiagnostics* diagnostics) {
    capture_.ReportFailuresTo(diagnostics);
  }

  ~CanEndpoint();
  CanEndpoint(const CanEndpoint&) = delete;
  CanEndpoint& operator=(const CanEndpoint&) = delete;

 private:
  /// A frame written to the socket whose echo has not been read yet.
  struct Sent {
    link::CanWireFrame frame;
    Time t_scheduled{};
    WallTime t_write_mono{};
    bool captured = false;  // virtual mode: captured at its emulated time already
  };
  void Capture(CaptureDir dir, Time t, WallTime wall, const link::CanWireFrame& f);
  /// Reads what the socket holds, captures it in that order, keeps others' frames for PollBus.
  void ReadBus(Time t_now, const link::RealtimePacer* pacer, Duration wait);
  /// One frame read off the socket: an echo of ours, or another's (captured or kept).
  void Take(const link::ReceivedCanFrame& r, Time t_now, const link::RealtimePacer* pacer);
  /// Virtual mode: reads until every frame sent on the interface so far has been read, or `limit`.
  void AwaitSentFrames(Time t_now, Duration limit);
  void OnEcho(const link::ReceivedCanFrame& r, Time t, WallTime mono);
  /// Captures the oldest frame still awaiting its echo at its write time.
  void CaptureUnechoed();
  /// Writes the arrivals whose capture waits (TakeArrivals) up to emulated time `t`.
  void CaptureArrivalsUpTo(Time t);
  /// Emulated time and CLOCK_MONOTONIC of a received frame: its kernel stamp (real time).
  std::pair<Time, WallTime> BusTime(const link::ReceivedCanFrame& r,
                                    const link::RealtimePacer& pacer);

  link::SocketCanPort port_;
  UnixTime start_utc_;
  link::CandumpLogWriter candump_;
  CaptureWriter capture_;
  std::deque<CanFrame> pending_;
  std::deque<Sent> awaiting_echo_;
  std::vector<CanFrame> inbox_;  // others' frames read, not yet returned by PollBus
  bool stamp_at_turns_ = false;
  std::vector<link::CanWireFrame> unstamped_;  // others' frames read, awaiting TakeArrivals
  std::deque<std::pair<Time, link::CanWireFrame>> arrivals_;  // stamped, capture not yet written
  std::optional<link::RealtimePacer> pacer_;  // real time: a copy of the run's clock mapping
  Duration realtime_minus_mono_{};            // CLOCK_REALTIME − CLOCK_MONOTONIC at start
  Time t_last_capture_{};                     // captures never go back in time
  BusTxCounter tx_counter_;                   // frames sent on the interface (vcan only)
  std::uint64_t frames_read_ = 0;             // frames read off the socket, echoes included
  std::uint64_t sent_frames_wait_timeouts_ = 0;
  QuantileSketch schedule_error_us_;
};

}  // namespace hil::harness

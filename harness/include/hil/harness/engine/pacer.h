#pragma once
/// @file
/// How the engine's step meets the wall clock: a strategy chosen once per run (engine.h).
///
///   VirtualPacer     free-running emulated time, as fast as the machine goes; bytes leave when
///                    they are made, through the virtual write queue (virtual_gate.h).
///   WallClockPacer   emulated time held to the wall clock with a speed factor (1: real time,
///                    else scaled); a pacing thread writes each byte and frame at its wall time.
///   LockstepPacer    a closed loop held to the wall clock: virtual mode's step (the same bytes),
///                    each action waiting for its wall-clock time; a slow host delays the run.
///
/// The pacer owns the path bytes take to the links (it decides when they leave); the host
/// turns (host_turns.h) decide when what the hosts wrote is read.

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/wall_time.h"
#include "hil/harness/engine/engine_devices.h"

namespace hil::harness {

class DeviceIo;
class VirtualGate;

/// The run's stepping, named (report.json's closed_loop.stepping).
enum class Stepping { kVirtual, kFreeRunning, kLockstep };
/// "virtual", "free_running", "lockstep".
const char* SteppingName(Stepping stepping);

/// One step's times: the earliest device event, the run's end, and the first action the step
/// takes (the event, or host bytes, a bus frame or a host turn due before it; never after t_end).
struct StepTimes {
  Time t_event{}, t_end{}, t_action{};
};

/// Lockstep: the actions paced, those served more than kLateNs after their wall-clock time, and
/// the largest delay (wall clock).
struct PaceLateness {
  static constexpr Duration kLate = std::chrono::milliseconds(1);
  std::uint64_t actions = 0, late = 0;
  Duration max_late{};
  /// One action due at wall instant `due`, served at wall instant `now`. Returns whether it must
  /// wait.
  bool Note(WallTime due, WallTime now);
};

/// The threads a wall-clock pacer ran ({"events" | "pacing", their scheduling and CPU}).
using PacingThreads = std::vector<std::pair<std::string, link::ThreadSchedule>>;

class Pacer {
 public:
  virtual ~Pacer() = default;
  virtual Stepping stepping() const = 0;
  /// The wall clock emulated time is held to (speed factor, t = 0's instant); null when it runs
  /// free (VirtualPacer).
  virtual const link::RealtimePacer* wall_clock() const { return nullptr; }

  /// Before the first event (a pacing thread starts here).
  virtual void Start(EngineDevices& devices) { (void)devices; }
  /// The run ends: `drain`, once every byte and frame has left, else at once.
  virtual void End(bool drain) { (void)drain; }
  /// The scheduling and CPU of the threads that paced the run (none for VirtualPacer).
  virtual PacingThreads threads() const { return {}; }
  /// The endpoints' lock while another thread writes to them (an empty lock otherwise).
  virtual std::unique_lock<std::mutex> LinksLock() { return {}; }
  /// The gate that keeps the host's links in order (virtual writes only; see VirtualWriteQueue).
  virtual void UseGate(VirtualGate& gate) { (void)gate; }

  /// Before the step at `step`: waits for its wall-clock time. True when it waited short of it
  /// (reading the hosts meanwhile) and the step must be picked again.
  virtual bool Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) = 0;
  /// Lockstep: how late the actions were served (nothing paced otherwise).
  virtual PaceLateness lateness() const { return {}; }
  /// The step's event has been served (lockstep: what it made leaves now, at its time).
  virtual void EndOfStep(DeviceIo& io) { (void)io; }

  /// A device's message is queued on `ep` (`bytes` bytes, its first ready at `t_ready`).
  virtual void Queued(SerialEndpoint& ep, std::size_t bytes, Time t_ready) = 0;
  /// After a device's output was queued (`lock`: LinksLock()'s, released here): sends what may
  /// go now, writes through the gate only when `write` (it has not given up). False when the
  /// gate gave up a wait.
  virtual bool Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) = 0;
  /// Writes everything queued for the virtual writes now (false: the gate gave up a wait).
  virtual bool SendAll() { return true; }
  /// The run is over: what is still queued leaves (false: the gate gave up a wait).
  virtual bool Flush(DeviceIo& io) = 0;

  /// The emulated time of host bytes read now: `t_host` (virtual time), or their arrival on the
  /// wall clock but not before the last event the devices computed.
  virtual Time HostBytesTime(Time t_host, Time t_last_event) const {
    (void)t_last_event;
    return t_host;
  }
  /// Whether host bytes are captured without a wall time (virtual time: they have none).
  virtual bool host_bytes_virtual() const { return true; }
  /// The clock that stamps what arrives on the bus at its own time (free-running real time); null:
  /// frames take the engine's emulated time (the last event).
  virtual const link::RealtimePacer* bus_stamp_clock() const { return nullptr; }
  /// The emulated time the bus is read at (`t_last_event`, or now on the wall clock).
  virtual Time BusTime(Time t_last_event) const { return t_last_event; }
  /// After an event: frames others put on the bus reach the devices at their bus time (free
  /// running) or wait for a host turn (the virtual turns queue them; nothing here).
  virtual void RouteBusFrames(DeviceIo& io, DeviceOutput& out) {
    (void)io;
    (void)out;
  }
};

}  // namespace hil::harness

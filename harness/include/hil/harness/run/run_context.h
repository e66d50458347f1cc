#pragma once
/// @file
/// The mutable state of one run beside the immutable Scenario (Drake: System vs Context; MuJoCo:
/// mjModel vs mjData). RunScenario goes through five phases that share it (run_phases.h):
/// prepare (the run folder, the devices and their links, the process under test), execute (the
/// engine, watched by a RunWatchdog), drain (the host reads every byte and finishes its
/// output), evaluate (against the truth) and write (the run folder's files, report.json last).

#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/core/run_diagnostics.h"
#include "hil/harness/core/truth_table.h"
#include "hil/harness/dut/controller_process.h"
#include "hil/harness/dut/estimate_collector.h"
#include "hil/harness/dut/estimator_process.h"
#include "hil/harness/dut/group_reaper.h"
#include "hil/harness/engine/clocked_host_turns.h"
#include "hil/harness/engine/engine.h"
#include "hil/harness/engine/pacer.h"
#include "hil/harness/engine/virtual_gate.h"
#include "hil/harness/faults/byte_faults.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/faults/fault_report.h"
#include "hil/harness/lockstep/lockstep_host.h"
#include "hil/harness/report/report.h"
#include "hil/harness/run/device_set.h"
#include "hil/harness/run/fix_baseline.h"
#include "hil/harness/run/progress.h"
#include "hil/harness/run/run.h"
#include "hil/harness/run/run_scoring.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// A file descriptor closed with its owner.
struct OwnedFd {
  int fd = -1;
  OwnedFd() = default;
  OwnedFd(const OwnedFd&) = delete;
  OwnedFd& operator=(const OwnedFd&) = delete;
  ~OwnedFd();
};

struct RunContext {
  /// Fixes what the options decide (seed, silence timeout, times); the phases fill the rest.
  RunContext(const Scenario& scenario, const RunOptions& options);

  const Scenario& scenario;
  const RunOptions& options;
  WallTime wall_start{};
  std::string dir;  ///< the run folder, absolute
  std::uint64_t seed;
  double silence_s;
  Duration silence;
  Time t_end, t_from;  ///< the scenario's end; the first time evaluated
  RunReport report;

  /// The run's diagnostics (the first file of the run folder that could not be written): the
  /// captures and the collector note into them, so they are declared before those and outlive them.
  RunDiagnostics diagnostics;

  /// Kills the run's process groups if hil dies (group_reaper.h); set by RunScenario.
  GroupReaper* reaper = nullptr;

  // prepare
  FaultRecorder fault_recorder;
  DeviceSet set;
  std::unique_ptr<link::PtyPort> nav_pty;  ///< output nmea_pty: the pty the estimator writes
  std::set<std::string> host_links;  ///< the links the host reads (none named: all; HostReads)
  /// Closed loop: the links only the controller reads (read in the lockstep while it runs).
  std::set<std::string> controller_links;
  bool controller_gone = false;  ///< the controller has ended: its links are no longer read
  /// navd's [input] merge_window_s as navd.conf sets it (0: off; virtual mode sets it for navd,
  /// and the gate then lets the links run apart by half of it: kNavdMergeWindowS)
  double navd_merge_window_s = 0;
  std::ofstream fixes_csv;
  /// --lockstep: the clock shared with the host processes, the library they preload, and whether
  /// the run went that way (false: the /proc probe paced it after all).
  std::optional<lockstep::LockstepHost> shared_clock;
  std::string preload_library;
  bool clocked = false;
  /// the host turns of a clocked run (owned by the engine), to ask whether they wrote ahead
  const ClockedHostTurns* clocked_turns = nullptr;
  std::optional<EstimatorProcess> estimator;
  /// Closed loop: the controller (in the estimator's process group) and the FIFO navd writes its
  /// NMEA solution into, held open by the run so that neither side waits for the other.
  std::optional<ControllerProcess> controller;
  OwnedFd nav_fifo;
  OwnedFd odometry_fifo;  ///< navd_mode gyro_odometry: the controller forwards the encoders here
  WallTime estimator_start{};
  /// How the run meets the wall clock (engine/pacer.h: virtual, free running, lockstep), and
  /// the path its bytes take to the links.
  std::unique_ptr<Pacer> pacer;
  std::optional<EstimateCollector> collector;
  EstimatorHealth health;

  // execute
  std::optional<ByteFaultInjector> byte_faults;
  std::optional<ProgressLine> progress;
  std::optional<VirtualGate> gate;  ///< virtual mode (or lockstep) with an estimator
  std::optional<Engine> engine;
  std::optional<FixBaseline> baseline;
  std::optional<TruthTableBuilder> truth_builder;
  /// The evaluation as the run goes (run_scoring.h); after truth_builder, which it asks.
  std::optional<RunScoring> scoring;
  std::vector<EstimateRecord> taken_estimates, taken_fixes;  ///< AskTruth's, reused

  // why the run ends early: the estimator hung; a signal, the run folder, a closed port
  std::optional<std::string> hang, stop_reason;
  Time t_now{};  ///< the latest event time served

  /// True when the run must stop for a signal or a file that could not be written (sets
  /// stop_reason the first time).
  bool Interrupted();
  bool EstimatorRunning() { return estimator && estimator->Running(); }
  /// Whether the host reads `ep` now: one of host_links (all when none is named), and not a link
  /// only the controller read once it has ended.
  bool HostReads(const SerialEndpoint& ep) const;
  /// The controller has ended (a controller_stop fault, or on its own): the gate no longer waits
  /// for the links only it read, so the run goes on and the actuators see the commands stop.
  void ControllerGone();
  /// Wall time since the estimator's last output (or its start).
  Duration SilentFor() const;
  /// Hands the solutions and fixes that came since last time to the scoring, which asks the
  /// truth builder for their times, lets it follow the run and scores what it has sampled.
  void AskTruth();
  /// Nothing stopped the run early so far and the estimator still runs.
  bool Healthy() { return !hang && !stop_reason && EstimatorRunning(); }
};

/// An estimator's output (stdout, or its NMEA pty) may reach kOutputBaseBytes plus
/// kOutputBytesPerEmulatedS per emulated second so far; more is a flood that stops the run
/// (issue 40.2: `cat /dev/urandom` as the estimator froze a virtual run at t = 0.6 s and wrote
/// 4.2 GB). Our choice: navd fusing GNSS and IMU at 10 Hz writes 8.6 kB per emulated second
/// (seed000_gps_imu --short: 1 028 945 bytes in 120 s), so the budget leaves it 7x; the base
/// covers a verbose start.
inline constexpr std::uint64_t kOutputBaseBytes = 16ull << 20;
inline constexpr std::uint64_t kOutputBytesPerEmulatedS = 64ull << 10;
/// The output allowed by emulated time `t_s` (s).
std::uint64_t OutputBudgetBytes(double t_s);

/// "%g" of seconds, and "%.1f" of a time, for messages.
std::string SecondsText(double s);
std::string SecondsText(Time t);

}  // namespace hil::harness

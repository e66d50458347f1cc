#pragma once
/// @file
/// One run of a scenario end to end: truth → device emulators → links → the estimator under test
/// → evaluation → reports in the run folder.
///
/// Scheduling (one engine owns the clock, engine/engine.h). At each event time tₛ, in order:
///   1. emulators sample the truth x(tₛ) (CVODE dense output) and produce whole messages;
///   2. each message enters its device's UART queue, which gives every byte its emulated time
///      (or drops the message whole when the transmit buffer is full);
///   3. the link delivers the bytes: in virtual mode at once (the bytes keep their emulated times
///      in the capture), in real-time/scaled mode each byte at its wall-clock UART time;
///   4. bytes from the host are read and logged with their times (virtual mode: at host turns,
///      with emulated arrival times as deterministic as the device's bytes;
///      engine/virtual_host_turns.h).
/// The bytes produced depend only on the scenario and the seed, never on the mode
/// (engine/engine.h).
///
/// The estimator under test is watched throughout: it ending early is a crash; no output for
/// the silence timeout (or, in virtual mode, not reading its input for that long) is a hang;
/// both fail the run, and the process group is always stopped at the end.

#include <cstdint>
#include <optional>
#include <string>

#include "hil/harness/report/report.h"
#include "hil/harness/run/run_priority.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

enum class RunMode { kVirtual, kRealtime };

struct RunOptions {
  std::string out_dir;                ///< run folder (created)
  std::optional<std::uint64_t> seed;  ///< overrides the scenario's seed
  RunMode mode = RunMode::kVirtual;
  double speed = 1.0;  ///< real-time speed-up (realtime mode; ≠ 1 is "scaled")
  std::optional<std::string> estimator_command;  ///< overrides the scenario's estimator command
  std::string navd_path;                         ///< substituted for {navd}
  std::string guidanced_path = "guidanced";      ///< substituted for {guidanced} (closed loop)
  bool progress = false;                         ///< live progress line on stderr
  bool emulate_only = false;  ///< `hil emulate`: no estimator; print the links and run
  std::optional<double>
      silence_timeout_s;  ///< overrides the scenario's estimator.silence_timeout_s
  bool html = true;       ///< write report.html and plots/
  /// Real time or scaled, closed loop: no lockstep; bytes leave at their UART times and the
  /// hosts' commands act at their arrival (not deterministic; RunContext::lockstep).
  bool free_running = false;
  /// Nice value of hil and the hosts it starts (run_priority.h); 0 leaves it as it is. Real time:
  /// only a raised priority (below 0) has the run's threads ask for SCHED_FIFO as well; at 0 or
  /// more they stay SCHED_OTHER at that nice value (`nice -n 19 hil emulate --nice 0` takes
  /// nothing from its neighbours).
  int nice = kDefaultRunNice;
  /// Virtual mode: the host processes run on hil's clock through libhil_lockstep.so (preloaded;
  /// harness/src/preload/README.md); the /proc probe paces them when one does not load it.
  bool lockstep = false;
  /// With `lockstep`: in an open loop whose programs hold the links read-only, hil writes ahead
  /// and the programs move their own clock (engine/lookahead_writer.h); false: a turn per message.
  bool lockstep_lookahead = true;
};

/// "virtual", "realtime" or "scaled" (real time with a speed-up other than 1).
std::string ModeName(RunMode mode, double speed);

/// Runs a scenario and writes the run folder. Returns the report (its pass() decides exit 0/1).
/// @throws std::runtime_error for setup failures (unwritable folder, estimator cannot start).
RunReport RunScenario(const Scenario& scenario, const RunOptions& options);

}  // namespace hil::harness

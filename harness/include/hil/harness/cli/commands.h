#pragma once
/// @file
/// The `hil` CLI, one subcommand per file in harness/src/cli/: each declares its options on the
/// app and returns how to run it; main() only parses and dispatches. Exit codes: 0 every
/// criterion passed (validate: conforms), 1 one failed, 2 bad input.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "hil/harness/scenario/scenario.h"

namespace hil::cli {

inline constexpr int kExitPass = 0, kExitFail = 1, kExitBadInput = 2;
/// A file of the run folder could not be written (disk full, EIO, a file size limit): the run's
/// figures are not all on disk (README, exit codes). 3 is the campaign's "runs missing".
inline constexpr int kExitWriteFailure = 4;
/// A run interrupted by a signal exits 128 + the signal (130 for SIGINT, 143 for SIGTERM, 129 for
/// SIGHUP), as a shell reports a command the signal ended.
inline constexpr int kExitInterruptedBase = 128;

/// A declared subcommand: run() is called when the command line chose it.
struct Subcommand {
  CLI::App* cmd = nullptr;
  std::function<int()> run;
};

Subcommand AddRun(CLI::App& app);           ///< hil run
Subcommand AddEmulate(CLI::App& app);       ///< hil emulate
Subcommand AddValidate(CLI::App& app);      ///< hil validate
Subcommand AddSuite(CLI::App& app);         ///< hil suite
Subcommand AddReplay(CLI::App& app);        ///< hil replay
Subcommand AddDataset(CLI::App& app);       ///< hil dataset
Subcommand AddExport(CLI::App& app);        ///< hil export
Subcommand AddCampaign(CLI::App& app);      ///< hil campaign (and its status, merge)
Subcommand AddCharacterize(CLI::App& app);  ///< hil characterize
Subcommand AddScenarioKeys(CLI::App& app);  ///< hil scenario-keys

/// This executable's path ("hil" when /proc cannot tell).
std::string SelfExecutable();
/// `name` beside this executable if it is there, else `name` (found on PATH).
std::string SiblingExecutable(const std::string& name);
/// How many runs of one scenario and seed the default folders tell apart (runs/NAME-seedN-999).
inline constexpr int kMaxRunFolderSuffix = 999;
/// `hil run`'s default folder, made here: runs/<name>-seed<seed>, or the first of
/// runs/<name>-seed<seed>-2, -3, ... that does not exist yet (a rerun never overwrites an earlier
/// run). Characters of the name other than letters, digits and `-_.+` become `_`.
/// @throws std::runtime_error when no folder can be made.
std::string DefaultRunFolder(const std::string& scenario_name, std::uint64_t seed);
/// Checks a `--seed` value: a whole number in [0, harness::kMaxSeed], the range a scenario's
/// `seed` key holds (CLI11 alone took -1 and 2^64 and ran them as 2^64 - 1).
CLI::Validator SeedValidator();
/// The scenario at `path` (empty: the embedded default); an invalid one is reported on stderr.
std::optional<harness::Scenario> LoadOrReport(
    const std::string& path, bool short_form = false,
    const std::vector<harness::ScenarioOverride>& overrides = {});

}  // namespace hil::cli

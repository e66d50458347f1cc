#pragma once
/// @file
/// `hil suite DIR`: every scenario file (*.yaml, *.yml) directly in DIR, optionally `repeat` times
/// with seeds seed, seed+1, … (the scenario's own seed when none is given), as the simplest
/// campaign (campaign_plan.h): the same engine runs each as a child `hil run` into
/// OUT/runs/<scenario file stem>[-seed<N>], `jobs` at a time, records it in OUT/records/ and
/// merges them into OUT/summary.json, OUT/junit.xml (a testsuite per run, a testcase per
/// criterion), OUT/report.md, which puts each scenario's figures (mean and spread over the seeds)
/// beside the reference figures of its `paper:` section (suite_report.h), and OUT/report.html.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hil::harness {

struct SuiteOptions {
  std::string dir;      ///< folder of scenario files
  std::string out_dir;  ///< suite output folder
  std::string hil_exe;  ///< the hil binary the runs use
  int jobs = 2;
  int repeat = 1;
  std::optional<std::uint64_t> seed;  ///< first seed of the repeats
  std::vector<std::string> run_args;  ///< passed to every `hil run` (e.g. --estimator CMD)
  bool short_form = false;            ///< each scenario's `short:` form (`hil run --short`)
};

struct SuiteResult {
  std::size_t runs = 0, passed = 0, failed = 0, invalid = 0;
  /// criteria across runs (scenarios' `statistical:` sections) that failed
  std::size_t criteria_failed = 0;
  /// 0 every run and every criterion across runs passed, 1 one failed, 2 bad input (no scenarios,
  /// an invalid scenario).
  int exit_code() const {
    return invalid > 0 || runs == 0 ? 2 : failed > 0 || criteria_failed > 0 ? 1 : 0;
  }
};

/// Runs the suite. @throws std::runtime_error when DIR cannot be read or OUT cannot be written.
SuiteResult RunSuite(const SuiteOptions& options);

/// The scenario files of a folder, sorted by name.
std::vector<std::string> SuiteScenarios(const std::string& dir);

}  // namespace hil::harness

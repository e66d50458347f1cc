#pragma once
// Internal to the harness: the tables of the loader's own sections (scenario_keys.h): the top
// level, estimator, criteria[] and evaluation, read by scenario.cc.
#include "hil/harness/scenario/estimator_kinds.h"
#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness::root_keys {

using enum KeyType;

// in the order of the loader's unknown-key message (its "known keys")
inline constexpr ScenarioKey kRoot[] = {
    {"name", kString, "", "required", 0, 0, "the scenario's name (run folder, reports)"},
    {"description", kString, "", "\"\"", 0, 0, "one line for the reports"},
    {"start_utc", kTime, "", "2026-06-10T08:00:00Z", 0, 0,
     "UTC of t = 0 (ISO 8601, e.g. \"2026-06-10T08:00:00Z\")"},
    {"duration_s", kNumber, "s", "60", 1, 7 * 86400, "the run's length in scenario time"},
    {"seed", kInteger, "", "1", 0, 9.3e18,
     "the seed of every random draw (`hil run --seed` replaces it)"},
    {"estimator", kMapping, "", "navd", 0, 0, "the program under test (section estimator)"},
    {"criteria", kList, "", "none", 0, 0, "pass/fail bounds (section criteria[])"},
    {"faults", kList, "", "none", 0, 0, "the fault timeline (vectors/scenarios/README.md)"},
    {"include", kList, "", "none", 0, 0,
     "files whose top-level keys are taken where this file has none (beside it, then in "
     "vectors/scenarios/lib and $HIL_SCENARIO_LIB)"},
    {"evaluation", kMapping, "", "from t = 0", 0, 0, "what is scored (section evaluation)"},
    {"default_criteria", kMapping, "", "all on", 0, 0,
     "the default criteria relaxed: {KEY: off | NUMBER} (vectors/scenarios/README.md)"},
    {"short", kMapping, "", "none", 0, 0,
     "the scenario's quick form: with `hil run --short` / `hil suite --short` its keys replace the "
     "top-level keys of the same name (any but name, include, paper and short)"},
};

inline constexpr ScenarioKey kEstimator[] = {
    {"command", kString, "", "{navd} --config {run_dir}/navd.conf", 0, 0,
     "shell command of the program under test; {navd}, {run_dir}, {seed} and each link name "
     "({ttyGPS}, {ttyNAV}, ...) are substituted (`hil run --estimator` replaces it)"},
    {"output", kChoice, "", "json_stdout", 0, 0,
     "how its solutions are read (vectors/scenarios/README.md, \"The estimator under test\")",
     kEstimatorOutputNames},
    {"navd_mode", kChoice, "", "gnss_only", 0, 0,
     "navd's filter mode, written into the generated navd.conf", kNavdModeNames},
    {"navd_filter", kMapping, "", "none", 0, 0,
     "further navd.conf [filter] keys, written as given (navd validates them)"},
    {"navd_input", kMapping, "", "none", 0, 0,
     "further navd.conf [input] keys; the device paths and bauds are hil's"},
    {"reference_point", kChoice, "", "auto", 0, 0,
     "WHICH POINT of the vehicle the solutions describe, the point the truth is taken at for "
     "scoring: antenna (the first receiver's antenna phase centre, gnss.antenna_lever_arm_m from "
     "the body reference point), imu (the IMU board, mcu.lever_arm_m), body (the reference point: "
     "rear-axle centre of the bicycle models, axle centre of diff_drive and skid_steer). auto: "
     "antenna for a GNSS-only navd, imu for navd fusing the IMU, body otherwise. Your own "
     "estimator fusing an IMU most likely outputs the IMU's position: say imu (or body, having "
     "moved it there), or a 0.5 m lever arm shows as a 0.5 m error that turns with the heading",
     kReferencePointNames},
    {"silence_timeout_s", kNumber, "s", "10", 0.5, 3600, "no solution for this long fails the run"},
    {"startup_s", kNumber, "s", "0", 0, 60,
     "wall time given to the program to open its devices before t = 0"},
};

inline constexpr ScenarioKey kCriterion[] = {
    {"metric", kString, "", "required", 0, 0,
     "a metric of report.json (vectors/scenarios/README.md), or navd.*, tracking.*, "
     "pass_to_pass.*, closed_loop.*, rtk_rover.*"},
    {"max", kNumber, "", "one of max, min, max_ratio_to_baseline", 0, 1e9,
     "passes when metric ≤ max"},
    {"min", kNumber, "", "one of max, min, max_ratio_to_baseline", 0, 1e9,
     "passes when metric ≥ min"},
    {"max_ratio_to_baseline", kNumber, "", "one of max, min, max_ratio_to_baseline", 0, 1e3,
     "passes when metric ≤ this × the baseline's (a campaign's)"},
    {"name", kString, "", "\"METRIC <= MAX\"", 0, 0, "the criterion's name in the reports"},
};

inline constexpr ScenarioKey kEvaluation[] = {
    {"from_s", kNumber, "s", "0", 0, 7 * 86400,
     "score from this time on (alignment, convergence before it)", kNoChoices, "[0, duration_s]"},
    {"reconverged_error_m", kNumber, "m", "1", 0.001, 1e4,
     "after an outage the solution has reconverged when its error is below this"},
};

}  // namespace hil::harness::root_keys

// hil characterize: Allan deviation, Welch PSD and fitted noise terms of an IMU log.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>

#include "hil/harness/characterize/characterize.h"
#include "hil/harness/characterize/characterize_report.h"
#include "hil/harness/characterize/imu_log_readers.h"
#include "hil/harness/cli/commands.h"

namespace hil::cli {
namespace {

struct CharacterizeArgs {
  CLI::App* cmd = nullptr;
  std::string log, format = "auto", json, svg, samples_csv;
  harness::CharacterizeOptions opt;
  double still_gyro_dps = 0.5;
  harness::CharacterizeReferences ref;
};

int Execute(CharacterizeArgs& a) {
  a.opt.still_options.gyro_std_radps = a.still_gyro_dps * std::numbers::pi / 180.0;
  try {
    const harness::ImuSeries log = harness::ReadImuLog(a.log, a.format);
    const harness::Characterization c = harness::Characterize(log, a.opt);
    std::fputs(harness::CharacterizationSummary(c).c_str(), stdout);
    if (!a.json.empty()) {
      std::ofstream out(a.json);
      out << harness::CharacterizationJson(c, a.log, a.ref).dump(1) << "\n";
      if (!out) throw std::runtime_error(a.json + ": cannot write");
    }
    if (!a.svg.empty()) harness::WriteCharacterizationSvgs(c, a.ref, a.svg);
    if (!a.samples_csv.empty()) harness::WriteAnalysedSamplesCsv(c, a.samples_csv);
    return kExitPass;
  } catch (const harness::NoStillPeriod& e) {
    std::fprintf(stderr, "hil: %s: %s\n", a.log.c_str(), e.what());
    return kExitFail;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

void DeclareReferences(CLI::App* cmd, CharacterizeArgs& a) {
  cmd->add_option("--reference-arw", a.ref.arw_deg_per_rthr,
                  "data-sheet angle random walk (deg/rt-h): a line on the gyro plots")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--reference-vrw", a.ref.vrw_mps_per_rthr,
                  "data-sheet velocity random walk (m/s/rt-h): a line on the accelerometer plots")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--reference-gyro-bi", a.ref.gyro_bias_instability_degph,
                  "data-sheet gyro bias instability (deg/h): its Allan floor, 0.664 B")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--reference-accel-bi", a.ref.accel_bias_instability_mps2,
                  "data-sheet accelerometer bias instability (m/s^2): its Allan floor")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--reference-label", a.ref.label, "legend name of the reference (data sheet)");
}

}  // namespace

Subcommand AddCharacterize(CLI::App& app) {
  auto a = std::make_shared<CharacterizeArgs>();
  a->cmd = app.add_subcommand(
      "characterize",
      "Overlapping Allan deviation (octave tau), Welch PSD and noise terms (ARW, VRW, bias "
      "instability, rate random walk) of an IMU log: KF-GINS IMU text, an IMU CSV with its RTKLIB "
      ".tag, or a run's captures/ttyIMU.cap");
  a->cmd->footer(
      "Examples:\n"
      "  hil characterize runs/still/captures/ttyIMU.cap --json still.json --svg plots\n"
      "  hil characterize imu_1730.csv --still --json walk.json     (imu_1730.csv.tag beside it)\n"
      "  hil characterize IMU.txt --from 100 --to 700 --reference-arw 0.3\n"
      "Exit codes: 0 done, 1 --still found no still period, 2 bad input (file, line, field).");
  a->cmd->add_option("LOG", a->log, "IMU log")->required();
  a->cmd
      ->add_option("--format", a->format, "auto (default: .cap, a CSV with LOG.tag, else KF-GINS)")
      ->check(CLI::IsMember({"auto", "kfgins", "csv-timetag", "capture"}));
  a->cmd->add_option("--from", a->opt.from_s, "window start, s from the log's first sample");
  a->cmd->add_option("--to", a->opt.to_s, "window end, s from the log's first sample");
  a->cmd->add_flag("--still", a->opt.still, "analyse the longest still period (in the window)");
  a->cmd
      ->add_option("--still-gyro-dps", a->still_gyro_dps,
                   "still: largest gyro std per axis in a window (default 0.5 deg/s)")
      ->check(CLI::PositiveNumber);
  a->cmd
      ->add_option("--still-accel-mps2", a->opt.still_options.accel_std_mps2,
                   "still: largest accelerometer std per axis in a window (default 0.1 m/s^2)")
      ->check(CLI::PositiveNumber);
  a->cmd
      ->add_option("--still-window-s", a->opt.still_options.window_s,
                   "still: window length (default 1 s)")
      ->check(CLI::PositiveNumber);
  a->cmd
      ->add_option("--still-min-s", a->opt.still_options.min_length_s,
                   "still: shortest period kept (default 5 s)")
      ->check(CLI::NonNegativeNumber);
  a->cmd->add_option("--step-s", a->opt.step_s, "grid step (default: the median sample interval)")
      ->check(CLI::PositiveNumber);
  a->cmd->add_option("--psd-segment", a->opt.psd_segment,
                     "Welch segment in samples, even (default: 2^k <= N/8, 16..4096)");
  a->cmd->add_option("--json", a->json, "write the results as JSON");
  a->cmd->add_option("--svg", a->svg, "write allan_gyro/allan_accel/psd_gyro/psd_accel.svg here");
  a->cmd->add_option("--samples-csv", a->samples_csv,
                     "write the analysed (resampled, windowed) samples as CSV, to check with "
                     "another tool");
  DeclareReferences(a->cmd, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

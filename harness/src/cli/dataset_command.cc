// hil dataset: KF-GINS-format test data from our truth and sensor models, and scoring a
// KF-GINS-format result against its truth.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/datasets/kfgins_dataset.h"
#include "hil/harness/datasets/kfgins_score.h"

namespace hil::cli {
namespace {

struct DatasetArgs {
  CLI::App* cmd = nullptr;
  CLI::App* gen = nullptr;
  CLI::App* score = nullptr;
  std::string dir, truth, nav;
  harness::KfginsDatasetOptions opt;
  bool paper004 = false;
  double from_s = 100, outage_length_s = 10;
  std::vector<double> outages;
};

constexpr double kPaper004Outages[] = {1400, 1450, 1480, 1500};

void Declare(CLI::App& app, DatasetArgs& a) {
  a.cmd = app.add_subcommand("dataset", "Standard datasets: KF-GINS-format test data, scoring");
  a.cmd->require_subcommand(1);
  a.gen = a.cmd->add_subcommand(
      "kfgins",
      "Write IMU.txt, GNSS.txt, truth.nav and kf-gins.yaml from our truth and a "
      "consumer-MEMS IMU model (deterministic for a seed)");
  a.gen->add_option("DIR", a.dir, "output folder")->required();
  a.gen->add_option("--seconds", a.opt.duration_s, "length (default 60)")
      ->check(CLI::Range(1.0, 86400.0));
  a.gen->add_option("--imu-hz", a.opt.imu_rate_hz, "IMU rate (default 200)")
      ->check(CLI::Range(10.0, 2000.0));
  a.gen->add_option("--gnss-hz", a.opt.gnss_rate_hz, "GNSS rate (default 1)")
      ->check(CLI::Range(0.1, 50.0));
  a.gen->add_option("--outage-at", a.opt.outage_start_s, "GNSS outage start (s), repeatable");
  a.gen->add_option("--outage-length", a.opt.outage_length_s, "outage length (default 10 s)");
  a.gen->add_flag("--paper004-outages", a.paper004, "paper 004's outages at 1400/1450/1480/1500 s");
  a.gen->add_option("--seed", a.opt.seed, "random seed (default 1)");
  a.score = a.cmd->add_subcommand("score", "Horizontal RMSE and outage errors of a .nav result");
  a.score->add_option("TRUTH", a.truth, "truth.nav")->required();
  a.score->add_option("NAV", a.nav, "KF_GINS_Navresult.nav")->required();
  a.score->add_option("--from-s", a.from_s, "score from this many s after the truth's start");
  a.score->add_option("--outage-at", a.outages, "outage start (s after the truth's start)");
  a.score->add_option("--outage-length", a.outage_length_s, "outage length (default 10 s)");
  a.score->add_flag("--paper004-outages", a.paper004, "outages at 1400/1450/1480/1500 s");
}

int Generate(DatasetArgs& a) {
  if (a.paper004)
    a.opt.outage_start_s.insert(a.opt.outage_start_s.end(), std::begin(kPaper004Outages),
                                std::end(kPaper004Outages));
  const harness::KfginsDatasetResult r = harness::WriteKfginsDataset(a.opt, a.dir);
  std::printf("wrote %s: %llu IMU lines, %llu GNSS lines\n", a.dir.c_str(),
              static_cast<unsigned long long>(r.imu_lines),
              static_cast<unsigned long long>(r.gnss_lines));
  return kExitPass;
}

int Score(DatasetArgs& a) {
  if (a.paper004) a.outages.assign(std::begin(kPaper004Outages), std::end(kPaper004Outages));
  const harness::KfginsScore s =
      harness::ScoreKfginsNav(harness::ReadKfginsNav(a.truth), harness::ReadKfginsNav(a.nav),
                              a.from_s, a.outages, a.outage_length_s);
  std::printf("horizontal RMSE %.4f m, max %.4f m, vertical RMSE %.4f m (%zu epochs from %.0f s)\n",
              s.rmse_h_m, s.max_h_m, s.rmse_v_m, s.epochs, a.from_s);
  double worst = 0;
  for (std::size_t k = 0; k < s.outage_max_h_m.size(); ++k) {
    std::printf("outage %.0f-%.0f s: max horizontal error %.4f m\n", a.outages[k],
                a.outages[k] + a.outage_length_s, s.outage_max_h_m[k]);
    worst = std::max(worst, s.outage_max_h_m[k]);
  }
  if (!s.outage_max_h_m.empty()) std::printf("worst outage %.4f m\n", worst);
  return kExitPass;
}

int Execute(DatasetArgs& a) {
  try {
    return a.gen->parsed() ? Generate(a) : Score(a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace

Subcommand AddDataset(CLI::App& app) {
  auto a = std::make_shared<DatasetArgs>();
  Declare(app, *a);
  return {a->cmd, [a] { return Execute(*a); }};
}

}  // namespace hil::cli

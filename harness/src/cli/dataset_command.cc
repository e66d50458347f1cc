// hil dataset: KF-GINS-format test data from our truth and sensor models, real logs imported into
// the same format, and scoring a KF-GINS-format result against its truth.
#include <cstdio>
#include <memory>

#include "hil/harness/cli/commands.h"
#include "hil/harness/datasets/dataset_import.h"
#include "hil/harness/datasets/kfgins_dataset.h"
#include "hil/harness/datasets/kfgins_score.h"
#include "hil/harness/datasets/outage_score.h"

namespace hil::cli {
namespace {

struct DatasetArgs {
  CLI::App* cmd = nullptr;
  CLI::App* gen = nullptr;
  CLI::App* score = nullptr;
  CLI::App* import = nullptr;
  std::string dir, truth, nav, windows_file, std_file, accel_unit = "g", gyro_unit = "dps";
  std::string time_offset = "auto";
  harness::KfginsDatasetOptions opt;
  harness::DatasetImportOptions imp;
  std::vector<double> lever{0, 0, 0};
  bool paper004 = false, json = false;
  double from_s = 100, outage_length_s = 10;
  std::vector<double> outages;
};

constexpr double kPaper004Outages[] = {1400, 1450, 1480, 1500};

void DeclareGenerate(DatasetArgs& a) {
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
}

void DeclareScore(DatasetArgs& a) {
  a.score = a.cmd->add_subcommand("score", "Errors of a .nav result against a truth .nav");
  a.score->add_option("TRUTH", a.truth, "truth.nav")->required();
  a.score->add_option("NAV", a.nav, "KF_GINS_Navresult.nav")->required();
  a.score->add_option("--from-s", a.from_s,
                      "score from this many s after the truth's start (default 100; 0 with "
                      "--windows/--std/--json)");
  a.score->add_option("--outage-at", a.outages, "outage start (s after the truth's start)");
  a.score->add_option("--outage-length", a.outage_length_s, "outage length (default 10 s)");
  a.score->add_flag("--paper004-outages", a.paper004, "outages at 1400/1450/1480/1500 s");
  a.score->add_option("--windows", a.windows_file,
                      "outage windows (outages.txt of `hil dataset import`): per-window scores");
  a.score->add_option("--std", a.std_file, "the result's KF_GINS_STD.txt: NEES");
  a.score->add_flag("--json", a.json, "per-window report as JSON");
}

void DeclareImportNoise(CLI::App* c, harness::ImportNoise& n) {
  c->add_option("--arw", n.arw_deg_rthr, "gyro ARW °/√h (default 0.228, ICM-45686 datasheet)");
  c->add_option("--vrw", n.vrw_mps_rthr, "accel VRW m/s/√h (default 0.0412, ICM-45686 datasheet)");
  c->add_option("--gbstd", n.gbstd_deg_hr, "gyro bias σ °/h (default 50)");
  c->add_option("--abstd", n.abstd_mgal, "accelerometer bias σ mGal (default 1000)");
  c->add_option("--gsstd", n.gsstd_ppm, "gyro scale σ ppm (default 5000)");
  c->add_option("--asstd", n.asstd_ppm, "accelerometer scale σ ppm (default 5000)");
  c->add_option("--corrtime", n.corrtime_hr, "bias correlation time h (default 1)");
  c->add_option("--initbgstd", n.initbgstd_deg_hr, "initial gyro bias σ °/h (default 100)");
  c->add_option("--initbastd", n.initbastd_mgal,
                "initial accelerometer bias σ mGal (default 5000)");
}

void DeclareImport(DatasetArgs& a) {
  harness::DatasetImportOptions& o = a.imp;
  CLI::App* c = a.import = a.cmd->add_subcommand(
      "import", "Real logs (RTKLIB .pos, IMU CSV + RTKLIB time tag, UBX) into KF-GINS files");
  c->add_option("DIR", a.dir, "output folder")->required();
  c->add_option("--reference", o.reference_pos, "RTKLIB .pos: the truth")->required();
  c->add_option("--gnss-pos", o.gnss_pos, "RTKLIB .pos as the GNSS input (default: --reference)");
  c->add_option("--gnss-ubx", o.gnss_ubx, "u-blox UBX log (NAV-PVT or NAV-POSLLH+VELNED) as input");
  c->add_flag("--ubx-height-msl", o.ubx_height_msl, "UBX: hMSL, not the ellipsoidal height");
  c->add_option("--imu-csv", o.imu_csv, "IMU CSV: ax ay az gx gy gz tick")->required();
  c->add_option("--imu-tag", o.imu_tag, "its RTKLIB time tag (default: CSV.tag)");
  c->add_option("--tag-fpos-bytes", o.tag_fpos_bytes, "file position size in the tag (4 or 8)");
  c->add_option("--accel-unit", a.accel_unit, "g or mps2 (default g)");
  c->add_option("--gyro-unit", a.gyro_unit, "dps or radps (default dps)");
  c->add_option("--tick-s", o.csv.tick_s, "seconds per tick count (default 0.001)");
  c->add_option("--imu-axes", o.imu_axes, "body FRD axes as signed sensor axes (default x,y,z)");
  c->add_option("--lever-arm", a.lever, "antenna in the body, FRD m (3 numbers)")->expected(3);
  c->add_option("--time-offset", a.time_offset, "IMU lag behind GPS time, s, or auto (default)");
  c->add_option("--max-offset-s", o.max_lag_s, "largest lag searched (default 1 s)");
  c->add_option("--reference-max-q", o.reference_max_q, "RTKLIB Q kept in the truth (default 2)");
  c->add_option("--gnss-max-q", o.gnss_max_q, "Q kept in the input (default 2: fix and float)");
  c->add_option("--outage-at", o.outages.at_s, "outage start, s after the start (repeatable)");
  c->add_option("--outage-every", o.outages.every_s, "one outage every so many s");
  c->add_option("--outage-first", o.outages.first_s, "first periodic outage, s after the start");
  c->add_option("--outage-length", o.outages.length_s, "outage length (default 10 s)");
  DeclareImportNoise(c, o.noise);
}

void Declare(CLI::App& app, DatasetArgs& a) {
  a.cmd = app.add_subcommand("dataset",
                             "Standard datasets: KF-GINS-format test data, real logs, scoring");
  a.cmd->require_subcommand(1);
  DeclareGenerate(a);
  DeclareScore(a);
  DeclareImport(a);
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

int Import(DatasetArgs& a) {
  harness::DatasetImportOptions& o = a.imp;
  if (a.accel_unit != "g" && a.accel_unit != "mps2")
    throw std::invalid_argument("--accel-unit: g or mps2");
  if (a.gyro_unit != "dps" && a.gyro_unit != "radps")
    throw std::invalid_argument("--gyro-unit: dps or radps");
  o.csv.accel_scale = a.accel_unit == "g" ? 9.80665 : 1.0;
  o.csv.gyro_scale = a.gyro_unit == "dps" ? 0.017453292519943295 : 1.0;
  o.lever_frd_m = {a.lever[0], a.lever[1], a.lever[2]};
  if (a.time_offset != "auto") o.imu_lag_s = std::stod(a.time_offset);
  o.have_outages = !o.outages.at_s.empty() || o.outages.every_s > 0;
  if (!o.gnss_pos.empty() && !o.gnss_ubx.empty())
    throw std::invalid_argument("--gnss-pos and --gnss-ubx: one GNSS input");
  const harness::DatasetImportResult r = harness::ImportDataset(o, a.dir);
  std::fputs(r.report.c_str(), stdout);
  return kExitPass;
}

int ScoreWindows(DatasetArgs& a) {
  const std::vector<harness::OutageWindow> w = a.windows_file.empty()
                                                   ? std::vector<harness::OutageWindow>{}
                                                   : harness::ReadOutageWindows(a.windows_file);
  std::vector<harness::KfginsStdLine> stds;
  if (!a.std_file.empty()) stds = harness::ReadKfginsStd(a.std_file);
  const harness::OutageScore s = harness::ScoreOutages(
      harness::ReadKfginsNav(a.truth), harness::ReadKfginsNav(a.nav), w,
      a.score->count("--from-s") ? a.from_s : 0.0, a.std_file.empty() ? nullptr : &stds);
  std::fputs((a.json ? harness::OutageScoreJson(s) : harness::OutageScoreText(s)).c_str(), stdout);
  return kExitPass;
}

int Score(DatasetArgs& a) {
  if (!a.windows_file.empty() || !a.std_file.empty() || a.json) return ScoreWindows(a);
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
    if (a.gen->parsed()) return Generate(a);
    if (a.import->parsed()) return Import(a);
    return Score(a);
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

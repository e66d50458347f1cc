#include "kfgins_mode.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "hil/estimator/datasets/kfgins_runner.h"
#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/navd_config.h"

namespace hil::navd {
namespace ds = hil::estimator::datasets;
namespace est = hil::estimator;

bool WantsKfginsMode(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--kfgins") == 0) return true;
  return false;
}

namespace {
int Usage(const char* problem) {
  std::fprintf(
      stderr,
      "navd: %s\nusage: navd --kfgins CONFIG.yaml [--navd-conf FILE] [--nhc-std-mps S] [--align]\n"
      "       [--mount-yaw-std-deg S] [--adaptive]\n"
      "  runs navd's filter on a KF-GINS dataset (the configuration's imupath, gnsspath)\n"
      "  and writes KF_GINS_Navresult.nav, KF_GINS_IMU_ERR.txt, KF_GINS_STD.txt to its\n"
      "  outputpath. --navd-conf takes the [filter] section of a navd.conf instead of\n"
      "  the parameters derived from the KF-GINS configuration; --nhc-std-mps adds\n"
      "  navd's non-holonomic constraint (a ground vehicle: no lateral or vertical body\n"
      "  velocity, this sigma in m/s, every 0.1 s) to them; --align lets the filter\n"
      "  align itself as navd does online instead of starting from initpos/initatt;\n"
      "  --mount-yaw-std-deg estimates the IMU's mounting yaw against the vehicle with\n"
      "  this prior sigma (with the NHC; 0 by default: held; a car: a few degrees);\n"
      "  --adaptive turns on the filter's adaptation to its innovations (estimator.md).\n",
      problem);
  return 2;
}

// an option's whole text as a finite number, else NaN (which fails every bound)
double FiniteNumber(const char* text) {
  char* end = nullptr;
  const double x = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(x) ? x : std::nan("");
}
}  // namespace

int KfginsMain(int argc, char** argv) {
  std::string config_path, navd_conf;
  bool self_align = false, adaptive = false;
  double nhc_std_mps = 0.0, mount_yaw_std_deg = -1.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--kfgins" && i + 1 < argc) {
      config_path = argv[++i];
    } else if (a == "--navd-conf" && i + 1 < argc) {
      navd_conf = argv[++i];
    } else if (a == "--nhc-std-mps" && i + 1 < argc) {
      nhc_std_mps = FiniteNumber(argv[++i]);
      if (!(nhc_std_mps > 0)) return Usage("--nhc-std-mps: not a positive number of m/s");
    } else if (a == "--mount-yaw-std-deg" && i + 1 < argc) {
      mount_yaw_std_deg = FiniteNumber(argv[++i]);
      if (!(mount_yaw_std_deg >= 0))
        return Usage("--mount-yaw-std-deg: not a non-negative number of degrees");
    } else if (a == "--adaptive") {
      adaptive = true;
    } else if (a == "--align") {
      self_align = true;
    } else {
      return Usage(("unknown or incomplete option '" + a + "'").c_str());
    }
  }
  try {
    const ds::KfginsConfig cfg = ds::LoadKfginsConfig(config_path);
    est::NavigatorParams params = ds::NavigatorParamsFromKfgins(cfg);
    if (!navd_conf.empty()) {
      params = est::NavdConfig::FromFile(est::ConfigFile::Load(navd_conf)).nav;
      params.fusion_horizon = est::Nanoseconds{0};  // the files are complete: no fusion delay
      params.gnss_max_latency = est::Nanoseconds{0};
    }
    if (nhc_std_mps > 0) params.ekf.nhc_std_mps = nhc_std_mps;
    if (adaptive) params.robust.adaptive = true;
    if (mount_yaw_std_deg >= 0) params.ekf.mount_yaw_std_rad = mount_yaw_std_deg * M_PI / 180.0;
    const ds::KfginsRunResult r = ds::RunKfgins(cfg, params, self_align);
    std::fprintf(
        stderr,
        "navd: kfgins %s: %llu IMU epochs (sow %.3f .. %.3f), %llu fixes: fused %llu, "
        "rejected %llu, resets %llu, mean NIS %.2f; IMU gaps %llu; wall %.3f s, CPU %.3f s "
        "= %.3f us per IMU epoch (reading, filter, writing)\n",
        config_path.c_str(), static_cast<unsigned long long>(r.imu_epochs), r.first_sow, r.last_sow,
        static_cast<unsigned long long>(r.gnss_records),
        static_cast<unsigned long long>(r.gnss_fused),
        static_cast<unsigned long long>(r.gnss_rejected),
        static_cast<unsigned long long>(r.gnss_resets), r.mean_nis_pos,
        static_cast<unsigned long long>(r.imu_gaps), r.wall_s, r.cpu_s,
        r.imu_epochs ? r.cpu_s * 1e6 / static_cast<double>(r.imu_epochs) : 0.0);
  } catch (const ds::DatasetError& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return 2;
  } catch (const est::ConfigError& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace hil::navd

#include "hil/estimator/datasets/kfgins_runner.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include <sys/stat.h>

#include "hil/estimator/angles.h"
#include "hil/estimator/datasets/kfgins_files.h"
#include "hil/estimator/datasets/kfgins_frames.h"
#include "hil/estimator/datasets/kfgins_output.h"

namespace hil::estimator::datasets {
namespace {

constexpr double kMgal = 1e-5;  // m/s²
constexpr double kDegPerHr = kDeg / 3600.0;

double CpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

GpsTime TimeOfSow(double sow) { return GpsTimeFromNs(std::llround(sow * 1e9)); }

GnssSample ToSample(const KfginsGnssRecord& r) {
  GnssSample g;
  g.t = TimeOfSow(r.sow);
  g.position = {r.lat_deg, r.lon_deg, r.height_m};
  g.pos_std_enu_m = SwapStd(r.std_ned_m);
  g.has_velocity = r.has_velocity;
  if (r.has_velocity) {
    g.vel_enu_mps = SwapNedEnu(r.vel_ned_mps);
    g.vel_std_enu_mps = SwapStd(r.vel_std_ned_mps);
  }
  g.fix_quality = 4;  // the files hold fixes only
  return g;
}

KfginsEpoch ToEpoch(const Navigator& nav, double sow) {
  const NavOutput o = nav.Output();
  KfginsEpoch e;
  e.sow = sow;
  e.lat_deg = o.position.lat_deg;
  e.lon_deg = o.position.lon_deg;
  e.height_m = o.position.height_m;
  e.vel_ned_mps = SwapNedEnu(o.v_N_mps);
  e.rpy_deg = EulerNedFromQuatEnuFlu(o.q_NB) / kDeg;
  e.gyro_bias_frd_deg_hr = FlipBody(o.gyro_bias_B) / kDegPerHr;
  e.accel_bias_frd_mgal = FlipBody(o.accel_bias_B) / kMgal;
  e.pos_std_ned_m = SwapStd(o.pos_std_enu_m);
  e.vel_std_ned_mps = SwapStd(o.vel_std_enu_mps);
  e.att_std_deg = SwapStd(o.att_std_rad) / kDeg;
  const EkfMatrix& P = nav.covariance();
  for (int i = 0; i < 3; ++i) {
    e.gyro_bias_std_deg_hr[i] =
        std::sqrt(P(ekf_index::kGyroBias + i, ekf_index::kGyroBias + i)) / kDegPerHr;
    e.accel_bias_std_mgal[i] =
        std::sqrt(P(ekf_index::kAccelBias + i, ekf_index::kAccelBias + i)) / kMgal;
  }
  return e;
}

void StartAt(const KfginsConfig& c, double sow, Navigator& nav) {
  const Eigen::Vector3d rpy = c.initatt_rpy_deg * kDeg;
  nav.InitializeAt(TimeOfSow(sow),
                   {c.initpos_deg_deg_m.x(), c.initpos_deg_deg_m.y(), c.initpos_deg_deg_m.z()},
                   SwapNedEnu(c.initvel_ned_mps), QuatEnuFluFromEulerNed(rpy));
  // the configuration's initial biases (FRD, °/h and mGal), zero where it gives none
  const Eigen::Vector3d bg = c.initgyrbias_deg_hr.value_or(Eigen::Vector3d::Zero()) * kDegPerHr;
  const Eigen::Vector3d ba = c.initaccbias_mgal.value_or(Eigen::Vector3d::Zero()) * kMgal;
  nav.SetImuBiases(FlipBody(ba), FlipBody(bg));
  // a scale factor is the same in FRD and navd's FLU body (an axis's sign cancels in it)
  if (c.initgyrscale_ppm) nav.SetGyroScale(*c.initgyrscale_ppm * 1e-6);
}

void EnsureDirectory(const std::string& dir) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw DatasetError(dir, 0, "outputpath: not a directory");
    return;
  }
  if (::mkdir(dir.c_str(), 0755) != 0) throw DatasetError(dir, 0, "outputpath: cannot create");
}

}  // namespace

NavigatorParams NavigatorParamsFromKfgins(const KfginsConfig& c) {
  NavigatorParams p;
  p.mode = NavMode::kEkf;
  p.fusion_horizon = Nanoseconds{0};
  p.gnss_max_latency = Nanoseconds{0};
  // the IMU file's times are GNSS time already: `hil dataset import` estimates the IMU's lag
  // (or takes the one given) and subtracts it, and the result is written at the IMU's times
  p.imu_lag.enabled = false;
  EkfParams& e = p.ekf;
  const KfginsImuNoise& n = c.imunoise;
  const double tau_s = n.corrtime_hr * 3600.0;
  e.gyro_noise_radps_rthz = n.arw_deg_rthr * kDeg / 60.0;
  e.accel_noise_mps2_rthz = n.vrw_mps_rthr / 60.0;
  e.gyro_bias_rw_radps2_rthz = n.gbstd_deg_hr * kDegPerHr * std::sqrt(2.0 / tau_s);
  e.accel_bias_rw_mps3_rthz = n.abstd_mgal * kMgal * std::sqrt(2.0 / tau_s);
  e.init_pos_std_m = c.initposstd_ned_m.maxCoeff();
  e.init_vel_std_mps = c.initvelstd_ned_mps.maxCoeff();
  e.init_roll_pitch_std_rad = std::max(c.initattstd_deg.x(), c.initattstd_deg.y()) * kDeg;
  e.init_yaw_std_rad = c.initattstd_deg.z() * kDeg;
  e.init_gyro_bias_std_radps =
      (c.initbgstd_deg_hr ? c.initbgstd_deg_hr->maxCoeff() : n.gbstd_deg_hr) * kDegPerHr;
  e.init_accel_bias_std_mps2 =
      (c.initbastd_mgal ? c.initbastd_mgal->maxCoeff() : n.abstd_mgal) * kMgal;
  e.lever_arm_B_m = FlipBody(c.antlever_frd_m);
  // KF-GINS's gyro scale factors: a first-order Gauss–Markov of σ gsstd and correlation time
  // corrtime, started at σ initsgstd (gsstd without it); navd's are the z scale (a random
  // constant) and the x and y scales (random walks of σ·√(2/τ), as the biases' above). The
  // accelerometers' scales (asstd) are not states: see kfgins.md.
  if (n.gsstd_ppm > 0) {
    const double init_ppm = c.initsgstd_ppm ? c.initsgstd_ppm->maxCoeff() : n.gsstd_ppm;
    e.gyro_scale_z_std = e.gyro_scale_xy_std = init_ppm * 1e-6;
    e.gyro_scale_xy_rw_rthz = n.gsstd_ppm * 1e-6 * std::sqrt(2.0 / tau_s);
  }
  return p;
}

KfginsRunResult RunKfgins(const KfginsConfig& c, const NavigatorParams& params, bool self_align) {
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = CpuSeconds();
  KfginsImuReader imu(c.Resolve(c.imupath), c.imudatalen);
  KfginsGnssReader gnss(c.Resolve(c.gnsspath));
  const std::string out_dir = c.Resolve(c.outputpath);
  EnsureDirectory(out_dir);
  KfginsOutputWriter out(out_dir);
  const auto nav = std::make_unique<Navigator>(params);  // large: its sample buffers
  KfginsRunResult res;
  KfginsImuRecord r;
  KfginsGnssRecord g;
  bool have_gnss = gnss.Next(g);
  bool started = false;
  GpsTime prev_t{};
  while (imu.Next(r)) {
    if (r.sow < c.starttime_s) continue;
    if (c.endtime_s > 0 && r.sow > c.endtime_s) break;
    const GpsTime t = TimeOfSow(r.sow);
    if (!started) {
      if (!self_align) StartAt(c, r.sow, *nav);
      started = true;
      res.first_sow = r.sow;
    } else {
      // every fix up to this epoch, before its increments (the interval is split at each fix)
      for (; have_gnss && g.sow <= r.sow; have_gnss = gnss.Next(g)) {
        if (g.sow <= res.first_sow) continue;
        nav->Push(ToSample(g));
        ++res.gnss_records;
      }
      ImuSample s;
      s.t = t;
      s.dt_s = static_cast<double>((t - prev_t).count()) * 1e-9;
      s.delta_angle_B_rad = FlipBody(r.dtheta_frd_rad);
      s.delta_velocity_B_mps = FlipBody(r.dvel_frd_mps);
      nav->Push(s);
      nav->Update();
    }
    prev_t = t;
    if (!nav->aligned()) continue;  // self-aligning: nothing to write before the alignment
    out.Write(ToEpoch(*nav, r.sow));
    ++res.imu_epochs;
    res.last_sow = r.sow;
  }
  out.Close();
  if (!started) throw DatasetError(c.Resolve(c.imupath), 0, "no IMU epoch at or after starttime");
  const NavigatorStats& st = nav->stats();
  res.gnss_fused = st.gnss_fused;
  res.gnss_rejected = st.gnss_rejected;
  res.gnss_resets = st.gnss_resets;
  res.imu_gaps = st.imu_gaps;
  res.mean_nis_pos = st.mean_nis_pos;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  res.cpu_s = CpuSeconds() - cpu0;
  return res;
}

}  // namespace hil::estimator::datasets

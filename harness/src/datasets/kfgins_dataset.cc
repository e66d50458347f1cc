#include "hil/harness/datasets/kfgins_dataset.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>

#include <Eigen/Geometry>
#include <sys/stat.h>

#include "hil/firmware_emu/angles.h"
#include "hil/harness/datasets/kfgins_text.h"
#include "hil/truth/path.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {
namespace {

// antenna in the body (FLU): 0.2 m ahead, 0.1 m to the right, 0.6 m up
const Eigen::Vector3d kLeverFlu(0.2, -0.1, 0.6);

truth::TruthConfig FieldTruth() {
  truth::TruthConfig c;
  c.origin = {30.5278, 114.3557,
              25.0};  // an open field; the values only set gravity and Earth rate
  truth::BoustrophedonSpec b;
  b.heading_deg = 30;
  b.row_length_m = 100;
  b.row_spacing_m = 8;
  b.rows = 20;
  b.turn_radius_m = 4;
  c.path = truth::MakeBoustrophedon(b);
  c.speed_mps = 1.0;
  return c;
}

struct ImuErrors {
  Eigen::Vector3d gyro_bias, accel_bias, gyro_drift = Eigen::Vector3d::Zero(),
                                         accel_drift = Eigen::Vector3d::Zero();
};

class Generator {
 public:
  Generator(const KfginsDatasetOptions& o, const std::string& dir)
      : o_(o), truth_(FieldTruth()), rng_(o.seed), files_(dir) {
    for (int i = 0; i < 3; ++i) {
      e_.gyro_bias[i] = o.gyro_turn_on_bias_deg_s * kDeg * n01_(rng_);
      e_.accel_bias[i] = o.accel_turn_on_bias_mg * 1e-3 * 9.80665 * n01_(rng_);
    }
  }

  KfginsDatasetResult Run() {
    const auto imu_period_ns = static_cast<std::int64_t>(std::llround(1e9 / o_.imu_rate_hz));
    const auto gnss_period_ns = static_cast<std::int64_t>(std::llround(1e9 / o_.gnss_rate_hz));
    const auto end_ns = static_cast<std::int64_t>(std::llround(o_.duration_s * 1e9));
    TruthSample prev = truth_.Sample(TimeFromNs(0));
    files_.WriteTruth(ToKfgins(prev, 0));
    KfginsDatasetResult res;
    for (std::int64_t t = imu_period_ns; t <= end_ns; t += imu_period_ns) {
      const TruthSample mid = truth_.Sample(TimeFromNs(t - imu_period_ns / 2));
      const TruthSample cur = truth_.Sample(TimeFromNs(t));
      files_.WriteImu(Sow(t), Imu(prev, mid, cur, static_cast<double>(imu_period_ns) * 1e-9));
      files_.WriteTruth(ToKfgins(cur, t));
      if (res.imu_lines++ == 0) WriteConfig(ToKfgins(cur, t));
      if (t % gnss_period_ns == 0 && !InOutage(t)) {
        files_.WriteGnss(Gnss(cur, t));
        ++res.gnss_lines;
      }
      prev = cur;
    }
    files_.Close();
    return res;
  }

 private:
  // the initial state is the truth at the first IMU epoch (KF-GINS starts there)
  void WriteConfig(const KfginsPva& first) const {
    KfginsYaml y;
    y.imudatarate_hz = o_.imu_rate_hz;
    y.starttime_s = first.sow;
    y.init = first;
    y.antlever_flu_m = kLeverFlu;
    // the filter is told the simulated noise × 1.5 and biases up to their turn-on σ
    y.arw_deg_rthr = 1.5 * o_.gyro_arw_deg_rthr;
    y.vrw_mps_rthr = 1.5 * o_.accel_vrw_mps_rthr;
    y.gbstd_deg_hr = o_.gyro_turn_on_bias_deg_s * 3600 + o_.gyro_bias_instability_deg_hr;
    y.abstd_mgal = (o_.accel_turn_on_bias_mg + o_.accel_bias_instability_mg) * 980.665;
    files_.WriteConfig(y);
  }

  double Sow(std::int64_t t_ns) const { return o_.start_sow + static_cast<double>(t_ns) * 1e-9; }

  bool InOutage(std::int64_t t_ns) const {
    const double t = static_cast<double>(t_ns) * 1e-9;
    for (double s : o_.outage_start_s)
      if (t > s && t <= s + o_.outage_length_s) return true;
    return false;
  }

  // increments of the interval (a, b] in FLU: Simpson's rule, then bias and noise
  KfginsImuIncrement Imu(const TruthSample& a, const TruthSample& m, const TruthSample& b,
                         double dt) {
    const Eigen::Vector3d dth = (a.w_IB_B_radps + 4.0 * m.w_IB_B_radps + b.w_IB_B_radps) * dt / 6;
    const Eigen::Vector3d dv = (a.f_B_mps2 + 4.0 * m.f_B_mps2 + b.f_B_mps2) * dt / 6;
    const double phi = std::exp(-dt / o_.bias_tau_s), q = std::sqrt(1 - phi * phi);
    KfginsImuIncrement inc;
    for (int i = 0; i < 3; ++i) {
      e_.gyro_drift[i] =
          phi * e_.gyro_drift[i] + q * o_.gyro_bias_instability_deg_hr * kDeg / 3600 * n01_(rng_);
      e_.accel_drift[i] =
          phi * e_.accel_drift[i] + q * o_.accel_bias_instability_mg * 1e-3 * 9.80665 * n01_(rng_);
      inc.dtheta_flu_rad[i] = dth[i] + (e_.gyro_bias[i] + e_.gyro_drift[i]) * dt +
                              o_.gyro_arw_deg_rthr * kDeg / 60 * std::sqrt(dt) * n01_(rng_);
      inc.dvel_flu_mps[i] = dv[i] + (e_.accel_bias[i] + e_.accel_drift[i]) * dt +
                            o_.accel_vrw_mps_rthr / 60 * std::sqrt(dt) * n01_(rng_);
    }
    return inc;
  }

  KfginsFix Gnss(const TruthSample& s, std::int64_t t_ns) {
    const Eigen::Vector3d noise(o_.gnss_std_h_m * n01_(rng_), o_.gnss_std_h_m * n01_(rng_),
                                o_.gnss_std_v_m * n01_(rng_));
    const Eigen::Vector3d p_ant = s.p_NB_N_m + s.q_NB * kLeverFlu + noise;
    const truth::Geodetic g = truth_.frame().ToGeodetic(p_ant);
    KfginsFix f;
    f.sow = Sow(t_ns);
    f.lat_deg = g.lat_deg;
    f.lon_deg = g.lon_deg;
    f.height_m = g.height_m;
    f.std_ned_m = {o_.gnss_std_h_m, o_.gnss_std_h_m, o_.gnss_std_v_m};
    return f;
  }

  KfginsPva ToKfgins(const TruthSample& s, std::int64_t t_ns) const {
    KfginsPva p;
    p.sow = Sow(t_ns);
    p.lat_deg = s.lat_deg;
    p.lon_deg = s.lon_deg;
    p.height_m = s.height_m;
    p.v_enu_mps = s.v_NB_N_mps;
    p.q_enu_flu = s.q_NB;
    return p;
  }

  KfginsDatasetOptions o_;
  truth::TruthIntegrator truth_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> n01_{0.0, 1.0};
  ImuErrors e_;
  KfginsTextFiles files_;
};

}  // namespace

KfginsDatasetResult WriteKfginsDataset(const KfginsDatasetOptions& o, const std::string& dir) {
  ::mkdir(dir.c_str(), 0755);
  Generator g(o, dir);
  return g.Run();
}

}  // namespace hil::harness

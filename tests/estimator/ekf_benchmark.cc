// Google Benchmark of the estimator core: one IMU predict, one GNSS update, and the whole seed-004
// run (1800 s, 100 Hz IMU, 10 Hz GNSS) through the Navigator, inputs generated beforehand so only
// the estimator is timed.
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "hil/estimator/navigator.h"

namespace hil::estimator {
namespace {

ErrorStateEkf MakeEkf() {
  EkfParams p;
  p.lever_arm_B_m = Eigen::Vector3d(1.2, 0, 2.2);
  p.gnss_error_tau_s = 30;
  p.gnss_error_std_m = 0.005;
  p.nhc_std_mps = 0.02;
  ErrorStateEkf e(p, EarthModel{});
  NavState s;
  s.v_N_mps = Eigen::Vector3d(1, 0, 0);
  e.Initialize(s);
  return e;
}

void BM_ImuPredict(benchmark::State& state) {
  ErrorStateEkf e = MakeEkf();
  const Eigen::Vector3d dth(1e-5, -2e-5, 3e-4), dv(1e-3, 2e-4, 0.0981);
  for (auto _ : state) {
    e.Predict(dth, dv, 0.01);
    benchmark::DoNotOptimize(e.covariance().data());
  }
}
BENCHMARK(BM_ImuPredict);

void BM_GnssPositionVelocityUpdate(benchmark::State& state) {
  ErrorStateEkf e = MakeEkf();
  for (auto _ : state) {
    state.PauseTiming();
    e.Predict(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.0981),
              0.01);  // keep P from collapsing
    const Eigen::Vector3d p = e.AntennaPosition() + Eigen::Vector3d(0.01, -0.01, 0.0);
    const Eigen::Vector3d v = e.AntennaVelocity();
    state.ResumeTiming();
    benchmark::DoNotOptimize(e.UpdatePosition(p, Eigen::Vector3d::Constant(0.015)));
    benchmark::DoNotOptimize(e.UpdateVelocity(v, Eigen::Vector3d::Constant(0.03)));
  }
}
BENCHMARK(BM_GnssPositionVelocityUpdate);

// state.range(0): the IMU tag lag estimate (ImuTimeOffset) on (1, navd's default) or off (0)
void BM_Seed004WholeRun(benchmark::State& state) {
  // straight line at 1 m/s heading east, level, with noise: 180 000 IMU and 18 000 GNSS samples
  constexpr GpsTime t0 = GpsTimeFromNs(1'400'000'000LL * 1'000'000'000LL);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0, 1);
  std::vector<ImuSample> imu;
  std::vector<GnssSample> gnss;
  const LocalTangentFrame frame({31.0, 121.4, 10.0});
  for (int k = 1; k <= 180000; ++k) {
    ImuSample s;
    s.t = t0 + Nanoseconds{k * 10'000'000LL};
    s.dt_s = 0.01;
    s.delta_angle_B_rad = Eigen::Vector3d(n(rng), n(rng), n(rng)) * 1e-6;
    s.delta_velocity_B_mps = Eigen::Vector3d(n(rng) * 1e-4, n(rng) * 1e-4, 9.7940 * 0.01);
    imu.push_back(s);
    if (k % 10 == 0) {
      GnssSample g;
      g.t = s.t;
      g.position = frame.ToLla(Eigen::Vector3d(k * 0.01 + 0.01 * n(rng), 0.01 * n(rng), 0.0));
      g.pos_std_enu_m.setConstant(0.015);
      g.has_velocity = true;
      g.vel_enu_mps = Eigen::Vector3d(1.0, 0, 0);
      g.vel_std_enu_mps.setConstant(0.03);
      gnss.push_back(g);
    }
  }
  for (auto _ : state) {
    NavigatorParams p;
    p.ekf.nhc_std_mps = 0.02;
    p.ekf.gnss_error_tau_s = 30;
    p.ekf.gnss_error_std_m = 0.005;
    p.imu_lag.enabled = state.range(0) != 0;
    Navigator nav(p);
    std::size_t gi = 0;
    for (const ImuSample& s : imu) {
      nav.Push(s);
      while (gi < gnss.size() && gnss[gi].t + Nanoseconds{50'000'000} <= s.t) nav.Push(gnss[gi++]);
      nav.Update();
    }
    benchmark::DoNotOptimize(nav.Output());
  }
  state.counters["imu_samples_per_s"] =
      benchmark::Counter(static_cast<double>(imu.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["realtime_factor"] = benchmark::Counter(
      1800.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Seed004WholeRun)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace hil::estimator

BENCHMARK_MAIN();

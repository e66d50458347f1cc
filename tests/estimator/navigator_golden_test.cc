// Change-indication golden of the navigator (after PX4's test/change_indication): a fixed,
// deterministic input set (the sensor-simulator fixture's seed 000 robot, seed 1: CVODE truth,
// consumer IMU at 10 Hz, NEO-5M-class GNSS at 1 Hz, a 10 s GNSS outage) goes through the EKF
// navigator, and its output every 0.5 s is compared with vectors/estimator/navigator_seed000.csv.
// Any change of the filter's behaviour shows as a difference; an intended one is accepted by
// regenerating the file with HIL_REGEN_VECTORS=1 and reviewing its diff.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "fixtures/seed000.h"
#include "fixtures/sensor_simulator.h"
#include "golden_file.h"

namespace hil::estimator::testing {
namespace {

std::string Row(const Navigator& nav, double t_s) {
  const NavOutput o = nav.Output();
  const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX();
  const double yaw_deg =
      std::fmod(90.0 - std::atan2(x.y(), x.x()) * 180.0 / std::numbers::pi + 360.0, 360.0);
  char b[320];
  std::snprintf(
      b, sizeof b, "%.1f,%.3f,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%u\n",
      t_s, o.valid ? static_cast<double>((o.t - SensorSimulator::kGpsStart).count()) * 1e-9 : 0.0,
      o.valid ? 1 : 0, o.p_N_m.x(), o.p_N_m.y(), o.p_N_m.z(), o.v_N_mps.x(), o.v_N_mps.y(),
      o.v_N_mps.z(), yaw_deg, o.pos_std_enu_m.x(), o.pos_std_enu_m.y(), o.pos_std_enu_m.z(),
      o.accel_bias_B.x(), o.gyro_bias_B.z() * 180.0 / std::numbers::pi, o.status);
  return b;
}

TEST(NavigatorGoldenTest, Seed000EkfOutputIsUnchanged) {
  const Eigen::Vector3d lever(0.84, 0.0, 0.6);
  Navigator nav(Seed000Params(lever));
  SensorSimulator sim(Seed000Truth(), ConsumerImu(), 10.0, Neo5mGnss(), lever, nav, 1);
  std::string csv =
      "# navigator output, seed 000 fixture, seed 1 (tests/estimator/navigator_golden_test.cc; "
      "regenerate with HIL_REGEN_VECTORS=1)\n"
      "t_s,tov_s,valid,p_e_m,p_n_m,p_u_m,v_e_mps,v_n_mps,v_u_mps,yaw_deg,std_e_m,std_n_m,std_u_m,"
      "accel_bias_x_mps2,gyro_bias_z_dps,status\n";
  // 40 s with GNSS, a 10 s outage (dead reckoning on the IMU), 10 s with GNSS again
  for (int k = 1; k <= 120; ++k) {
    if (k == 81) sim.stop_gnss();
    if (k == 101) sim.start_gnss();
    sim.run_for(0.5);
    csv += Row(nav, sim.now_s());
  }
  ASSERT_TRUE(nav.aligned());
  // Printed to 0.1 mm, 0.1 mm/s, 1e-4 °; compared within 2e-4 (two units of the last digit) so
  // that a last-bit floating-point difference between builds (optimisation level, FMA
  // contraction, sanitizers) that flips a rounding does not fail, while a change of behaviour
  // does. Integer fields (valid, status) and times are compared exactly by the same rule.
  hil::test::CheckOrWriteGolden("vectors/estimator/navigator_seed000.csv", csv,
                                {.numeric_tolerance = 2e-4});
}

}  // namespace
}  // namespace hil::estimator::testing

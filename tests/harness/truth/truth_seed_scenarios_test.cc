// The seed scenarios' truth end to end from their YAML files: the vehicle follows the planned
// path, and the figures (cross-track statistics, attitude ranges) are printed for the report.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {
namespace {

struct Stats {
  double mean_abs_xt = 0, max_abs_xt = 0, max_roll_deg = 0, max_pitch_deg = 0, max_f_horizontal = 0;
  TruthSample last;
};

Stats Drive(const Scenario& s, double rate_hz) {
  truth::TruthIntegrator truth(s.truth);
  Stats st;
  const auto n = static_cast<std::int64_t>(s.duration_s * rate_hz);
  for (std::int64_t k = 0; k <= n; ++k) {
    const TruthSample ts = truth.Sample(TimeFromSeconds(static_cast<double>(k) / rate_hz));
    st.mean_abs_xt += std::abs(ts.cross_track_m) / static_cast<double>(n + 1);
    st.max_abs_xt = std::max(st.max_abs_xt, std::abs(ts.cross_track_m));
    const Eigen::Matrix3d R = ts.q_NB.toRotationMatrix();
    st.max_roll_deg =
        std::max(st.max_roll_deg, std::abs(std::atan2(R(2, 1), R(2, 2))) * 180 / M_PI);
    st.max_pitch_deg = std::max(st.max_pitch_deg, std::abs(std::asin(R(2, 0))) * 180 / M_PI);
    st.max_f_horizontal = std::max(st.max_f_horizontal, ts.f_B_mps2.head<2>().norm());
    st.last = ts;
  }
  std::printf(
      "%s: |cross-track| mean %.3f m, max %.3f m; max |roll| %.2f deg, max |pitch| %.2f deg, "
      "max horizontal specific force %.2f m/s^2; end at (%.2f, %.2f) m\n",
      s.name.c_str(), st.mean_abs_xt, st.max_abs_xt, st.max_roll_deg, st.max_pitch_deg,
      st.max_f_horizontal, st.last.p_NB_N_m.x(), st.last.p_NB_N_m.y());
  return st;
}

std::string Source(const std::string& file) {
  const char* dir = std::getenv("HIL_SOURCE_DIR");
  return std::string(dir ? dir : ".") + "/tests/harness/truth/" + file;
}

TEST(TruthSeedScenariosTest, Seed003RectangleIsDrivenAroundAndBackToA) {
  const Scenario s = LoadScenario(Source("truth_seed003_rectangle.yaml"));
  const Stats st = Drive(s, 5);  // seed 003 sampled at 5 Hz
  EXPECT_LT(st.mean_abs_xt, 0.15);
  EXPECT_LT(st.max_abs_xt, 1.0);
  EXPECT_LT((st.last.p_NB_N_m.head<2>() - Eigen::Vector2d(-7, -7)).norm(), 0.5);
  EXPECT_NEAR(st.last.speed_mps, 0, 1e-3);
}

TEST(TruthSeedScenariosTest, Seed004TractorCoversTheFieldIn1800s) {
  const Scenario s = LoadScenario(Source("truth_seed004_field.yaml"));
  const Stats st = Drive(s, 10);  // seed 004's RTK rate
  EXPECT_LT(st.mean_abs_xt, 0.05);
  EXPECT_LT(st.max_abs_xt, 0.5);
  EXPECT_GT(st.max_roll_deg, 0.5);
  // after 1800 s at 1 m/s (path 1803.5 m) it is near the end of the tenth row (9 × 7.5 m east),
  // which runs south back to the field's start edge
  EXPECT_NEAR(st.last.p_NB_N_m.x(), 67.5, 0.05);
  EXPECT_GT(st.last.p_NB_N_m.y(), 0);
  EXPECT_LT(st.last.p_NB_N_m.y(), 10);
  EXPECT_LT(st.last.v_NB_N_mps.y(), -0.9);
}

}  // namespace
}  // namespace hil::harness

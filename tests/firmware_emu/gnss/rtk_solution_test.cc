// The rough RTK solution: float then fixed with the jump it makes, fix loss when satellites are
// shaded, wrong fixes off by whole cycles and held until re-fix; seeded and deterministic.
#include "hil/firmware_emu/gnss/rtk_solution.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/sky_shading.h"

namespace hil::gnss {
namespace {

std::vector<SatelliteView> Sky(int used) {
  std::vector<SatelliteView> s;
  const double az[] = {0, 70, 140, 210, 280, 35, 250, 110, 320};
  const double el[] = {15, 40, 25, 60, 30, 75, 20, 50, 45};
  for (int i = 0; i < 9; ++i) {
    SatelliteView v;
    v.svid = i + 1;
    v.azim_deg = az[i];
    v.elev_deg = el[i];
    v.used = i < used;
    v.cno_dbhz = 42;
    s.push_back(v);
  }
  return s;
}

struct Timeline {
  std::vector<RtkEpoch> epochs;
};

// 10 Hz epochs from 0 to `end_s`; `used(t_s)` satellites in view.
template <class F>
Timeline Drive(const RtkRoughness& cfg, std::uint64_t seed, double end_s, F used) {
  RtkSolution rtk(cfg, seed);
  Timeline r;
  for (int k = 0; k <= static_cast<int>(end_s * 10); ++k) {
    const double t_s = k * 0.1;
    r.epochs.push_back(rtk.Step(TimeFromSeconds(t_s), k == 0 ? 0.0 : 0.1, true, Sky(used(t_s))));
  }
  return r;
}

TEST(RtkSolution, FloatForTheTimeToFixThenFixedWithTheJumpOfTheFloatError) {
  RtkRoughness cfg;
  cfg.time_to_fix_s = 20;
  const Timeline r = Drive(cfg, 7, 40, [](double) { return 9; });
  for (int k = 0; k < 200; ++k) EXPECT_EQ(r.epochs[k].state, RtkState::kFloat) << k;
  for (int k = 200; k <= 400; ++k) EXPECT_EQ(r.epochs[k].state, RtkState::kFixed) << k;
  // float: decimetres at first, converging (sigma from 0.3 towards 0.05 m over 30 s)
  EXPECT_NEAR(r.epochs[0].sigma_h_m, 0.3 * std::sqrt(2.0), 1e-12);
  EXPECT_LT(r.epochs[199].sigma_h_m, r.epochs[0].sigma_h_m);
  EXPECT_GT(r.epochs[199].error_N_m.norm(), 0.0);
  // fixed: the state's error is gone (the receiver's cm noise is the model's)
  EXPECT_EQ(r.epochs[200].error_N_m.norm(), 0.0);
  EXPECT_EQ(r.epochs[200].sigma_h_m, 0.0);
}

TEST(RtkSolution, ShadedBelowTheMinimumTheFixFallsBackToFloatAndReFixes) {
  RtkRoughness cfg;
  cfg.time_to_fix_s = 5;
  cfg.refix_s = 3;
  cfg.min_sats_fixed = 6;
  // 9 satellites, 5 from 10 to 20 s, then 9 again
  const Timeline r = Drive(cfg, 7, 30, [](double t) { return t >= 10 && t < 20 ? 5 : 9; });
  EXPECT_EQ(r.epochs[99].state, RtkState::kFixed);
  for (int k = 100; k < 200; ++k) EXPECT_EQ(r.epochs[k].state, RtkState::kFloat) << k;
  // back at 20 s: float until refix_s after the loss has passed and enough satellites are back
  EXPECT_EQ(r.epochs[200].state, RtkState::kFixed);
  EXPECT_NEAR(r.epochs[100].sigma_h_m, 0.3 * std::sqrt(2.0), 1e-12);  // unconverged again
}

TEST(RtkSolution, WrongFixIsOffByWholeCyclesThroughTheGeometryAndHeldUntilReFix) {
  RtkRoughness cfg;
  cfg.time_to_fix_s = 5;
  cfg.refix_s = 2;
  cfg.wrong_fix_probability = 1.0;
  cfg.wrong_fix_hold_s = 10;  // 5…15 s
  cfg.wrong_fix_satellites = 2;
  const Timeline r = Drive(cfg, 11, 30, [](double) { return 9; });
  const RtkEpoch& first = r.epochs[50];
  ASSERT_EQ(first.state, RtkState::kFixed);
  ASSERT_TRUE(first.wrong_fix);
  // two satellites ±1 cycle: the least-squares image of ≤ 2 × 19 cm range errors
  EXPECT_GT(first.error_N_m.norm(), 0.01);
  EXPECT_LT(first.error_N_m.norm(), 1.0);
  EXPECT_EQ(first.sigma_h_m, 0.0);  // the receiver believes it: no float accuracy
  // held unchanged (same geometry here) for at least 5 s, then float, then a new fix
  for (int k = 50; k < 100; ++k) EXPECT_EQ(r.epochs[k].error_N_m, first.error_N_m) << k;
  int refloat = -1;
  for (int k = 100; k <= 150 && refloat < 0; ++k) {
    if (r.epochs[k].state == RtkState::kFloat) refloat = k;
  }
  ASSERT_GT(refloat, 0);
  EXPECT_EQ(r.epochs[refloat + 20].state, RtkState::kFixed);
}

TEST(RtkSolution, WrongFixRateAndSequenceFollowTheSeed) {
  RtkRoughness cfg;
  cfg.time_to_fix_s = 1;
  cfg.refix_s = 1;
  cfg.wrong_fix_probability = 0.25;
  cfg.wrong_fix_hold_s = 2;
  // lose the fix every 10 s so that it re-fixes often
  const auto used = [](double t) { return std::fmod(t, 10.0) < 1.0 ? 5 : 9; };
  RtkSolution a(cfg, 5), b(cfg, 5);
  for (int k = 0; k <= 20000; ++k) {
    const auto sky = Sky(used(k * 0.1));
    const RtkEpoch ea = a.Step(TimeFromSeconds(k * 0.1), 0.1, true, sky);
    const RtkEpoch eb = b.Step(TimeFromSeconds(k * 0.1), 0.1, true, sky);
    ASSERT_EQ(ea.error_N_m, eb.error_N_m) << k;
  }
  ASSERT_GT(a.fixes(), 150u);
  const double rate = static_cast<double>(a.wrong_fixes()) / static_cast<double>(a.fixes());
  EXPECT_NEAR(rate, 0.25, 0.08);
  RtkRoughness never = cfg;
  never.wrong_fix_probability = 0.0;
  RtkSolution c(never, 5);
  for (int k = 0; k <= 2000; ++k) c.Step(TimeFromSeconds(k * 0.1), 0.1, true, Sky(9));
  EXPECT_EQ(c.wrong_fixes(), 0u);
}

TEST(RtkSolution, NoFixNoState) {
  RtkSolution rtk(RtkRoughness{}, 1);
  const RtkEpoch e = rtk.Step(TimeFromSeconds(0), 0, false, Sky(9));
  EXPECT_EQ(e.state, RtkState::kNone);
}

}  // namespace
}  // namespace hil::gnss

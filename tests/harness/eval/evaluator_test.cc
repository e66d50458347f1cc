#include "hil/harness/eval/evaluator.h"

#include <gtest/gtest.h>

#include "hil/harness/report/report.h"

namespace hil::harness {
namespace {

truth::TruthConfig StraightNorth() {
  truth::TruthConfig c;
  c.origin = {35.0, 50.0, 100.0};
  c.heading_deg = 0;
  c.speed_mps = 1.0;
  return c;
}

TEST(EvaluatorTest, KnownOffsetGivesKnownMetrics) {
  const truth::TruthConfig cfg = StraightNorth();
  truth::TruthIntegrator truth(cfg);
  std::vector<EstimateRecord> recs;
  for (int k = 0; k < 10; ++k) {
    const TruthSample s = truth.Sample(TimeFromSeconds(k));
    // 3 m east, 4 m north of the truth: 5 m horizontal error everywhere
    const auto g = truth.frame().ToGeodetic(s.p_NB_N_m + Eigen::Vector3d(3, 4, -1));
    recs.push_back({TimeFromSeconds(k), g.lat_deg, g.lon_deg, g.height_m, std::nullopt,
                    std::nullopt, std::nullopt, WallTime{}});
  }
  const auto errs =
      CompareWithTruth(cfg, recs, Eigen::Vector3d::Zero(), Time{}, TimeFromSeconds(100));
  const AccuracyMetrics m = ComputeAccuracy(errs);
  EXPECT_EQ(m.samples, 10u);
  EXPECT_NEAR(m.horizontal_rmse_m, 5.0, 1e-6);
  EXPECT_NEAR(m.cep95_m, 5.0, 1e-6);
  EXPECT_NEAR(m.vertical_rmse_m, 1.0, 1e-6);
}

TEST(EvaluatorTest, CriteriaAgainstAbsoluteAndBaselineThresholds) {
  AccuracyMetrics est, base;
  est.samples = base.samples = 5;
  est.horizontal_rmse_m = 0.22;
  base.horizontal_rmse_m = 0.40;
  Criterion abs{"abs", "horizontal_rmse_m", 0.2, std::nullopt, std::nullopt, {}};
  Criterion rel{"rel", "horizontal_rmse_m", std::nullopt, std::nullopt, 0.6, {}};
  const auto r = EvaluateCriteria({abs, rel}, est, base);
  EXPECT_FALSE(r[0].pass);
  EXPECT_TRUE(r[1].pass);
  EXPECT_NEAR(r[1].threshold, 0.24, 1e-12) << "0.6 × 0.40";
  EXPECT_FALSE(EvaluateCriteria({abs}, AccuracyMetrics{}, base)[0].pass)
      << "no estimates must fail";
}

TEST(EvaluatorTest, PercentileInterpolates) {
  EXPECT_DOUBLE_EQ(Percentile({1, 2, 3, 4, 5}, 50), 3);
  EXPECT_DOUBLE_EQ(Percentile({0, 10}, 95), 9.5);
}

}  // namespace
}  // namespace hil::harness

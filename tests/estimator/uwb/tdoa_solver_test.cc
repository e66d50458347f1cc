// The closed-form TDOA solver (paper 003 eqs. 1–6) against exact geometry from
// vectors/uwb/tdoa_closed_form.csv (written by an independent Python script), plus degenerate and
// bad input: flagged, never NaN.
#include "hil/estimator/uwb/tdoa_solver.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "vector_files.h"

namespace hil::estimator::uwb {
namespace {

TdoaSolverConfig VectorAnchors() {
  TdoaSolverConfig c;
  c.p_W_anchor_m = {Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, -10), Eigen::Vector2d(10, 10),
                    Eigen::Vector2d(-10, 10)};
  return c;
}

TEST(TdoaSolverTest, GoldenVectorSolvesEveryPointAndFlagsEveryBaselinePoint) {
  const auto rows =
      hil::test::ReadCsvRows(hil::test::VectorPath("vectors/uwb/tdoa_closed_form.csv"));
  ASSERT_EQ(rows.size(), 76u);
  const TdoaSolver solver(VectorAnchors());
  int ok = 0, flagged = 0;
  for (const auto& r : rows) {
    SCOPED_TRACE(r[0]);
    ASSERT_EQ(r.size(), 7u);
    const Eigen::Vector2d truth(std::stod(r[1]), std::stod(r[2]));
    const Eigen::Vector3d d(std::stod(r[3]), std::stod(r[4]), std::stod(r[5]));
    const TdoaFix fix = solver.Solve(d);
    EXPECT_TRUE(fix.p_W_m.allFinite());
    EXPECT_EQ(std::string(ToString(fix.status)), r[6]);
    if (fix.ok()) {
      EXPECT_NEAR((fix.p_W_m - truth).norm(), 0.0, 1e-6);
      EXPECT_NEAR(fix.bs4_residual_m, 0.0, 1e-6);
      EXPECT_NEAR(fix.r1_m, (truth - Eigen::Vector2d(-10, -10)).norm(), 1e-6);
      ++ok;
    } else {
      EXPECT_EQ(fix.p_W_m, Eigen::Vector2d::Zero());
      ++flagged;
    }
  }
  EXPECT_EQ(ok, 71);
  EXPECT_EQ(flagged, 5);
}

TEST(TdoaSolverTest, RootChoiceUsesBs4WhenBothRootsAreAdmissible) {
  // Scan the field at 0.5 m: wherever eq. 6 has two admissible roots, BS4 must pick the truth.
  const TdoaSolver solver(VectorAnchors());
  const auto& bs = solver.config().p_W_anchor_m;
  int two_roots = 0;
  for (double x = -9.5; x <= 9.5; x += 0.5) {
    for (double y = -9.5; y <= 9.5; y += 0.5) {
      const Eigen::Vector2d p(x, y);
      const double r1 = (p - bs[0]).norm();
      const Eigen::Vector3d d((p - bs[1]).norm() - r1, (p - bs[2]).norm() - r1,
                              (p - bs[3]).norm() - r1);
      const TdoaFix fix = solver.Solve(d);
      if (!fix.ok()) continue;  // the diagonal's and edges' extensions do not cross the square
      EXPECT_NEAR((fix.p_W_m - p).norm(), 0.0, 1e-6) << x << "," << y;
      if (fix.admissible_roots == 2) ++two_roots;
    }
  }
  EXPECT_GT(two_roots, 0) << "the scan never exercised the root choice";
}

TEST(TdoaSolverTest, TimeDifferencesUseThePapersSpeedOfLight) {
  EXPECT_DOUBLE_EQ(RangeDifferenceFromTdoa_m(1e-9), 0.3);  // 1 ns = 0.30 m
}

TEST(TdoaSolverTest, NoisyDifferencesStayFiniteAndNear) {
  const TdoaSolver solver(VectorAnchors());
  const auto& bs = solver.config().p_W_anchor_m;
  const Eigen::Vector2d p(3.0, -2.0);
  const double r1 = (p - bs[0]).norm();
  Eigen::Vector3d d((p - bs[1]).norm() - r1, (p - bs[2]).norm() - r1, (p - bs[3]).norm() - r1);
  d += Eigen::Vector3d(0.03, -0.02, 0.05);  // a few centimetres of range-difference error
  const TdoaFix fix = solver.Solve(d);
  ASSERT_TRUE(fix.ok());
  EXPECT_LT((fix.p_W_m - p).norm(), 0.2);
  EXPECT_GT(std::abs(fix.bs4_residual_m), 0.0);
}

TEST(TdoaSolverTest, BadAndImpossibleInputIsFlaggedNotNaN) {
  const TdoaSolver solver(VectorAnchors());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  TdoaFix f = solver.Solve(Eigen::Vector3d(nan, 0, 0));
  EXPECT_EQ(f.status, TdoaStatus::kBadInput);
  EXPECT_TRUE(f.p_W_m.allFinite());
  f = solver.Solve(Eigen::Vector3d(25.0, 0, 0));  // longer than the 20 m baseline
  EXPECT_EQ(f.status, TdoaStatus::kOnBaseline);
  EXPECT_TRUE(f.p_W_m.allFinite());
}

TEST(TdoaSolverTest, CollinearAnchorsAreRejectedAtConstruction) {
  TdoaSolverConfig c = VectorAnchors();
  c.p_W_anchor_m[2] = Eigen::Vector2d(30, -10);  // BS3 on the line BS1–BS2
  EXPECT_THROW(TdoaSolver{c}, std::invalid_argument);
  c = VectorAnchors();
  c.p_W_anchor_m[0].x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(TdoaSolver{c}, std::invalid_argument);
}

}  // namespace
}  // namespace hil::estimator::uwb

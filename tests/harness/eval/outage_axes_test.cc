// Per-axis maxima of the error inside each GNSS outage (paper 004 states its result in E, N and U),
// and their worst values as criterion metrics.
#include <gtest/gtest.h>

#include "hil/harness/eval/outage_metrics.h"
#include "hil/harness/report/report.h"

namespace hil::harness {
namespace {

ErrorSample At(double t_s, double e, double n, double u) {
  ErrorSample s;
  s.t = TimeFromSeconds(t_s);
  s.err_enu_m = Eigen::Vector3d(e, n, u);
  return s;
}

TEST(OutageAxesTest, LargestAbsoluteErrorPerAxisInsideEachOutage) {
  FaultTimeline faults;
  Fault a;
  a.kind = FaultKind::kGnssOutage;
  a.start = TimeFromSeconds(10);
  a.end = TimeFromSeconds(20);
  Fault b = a;
  b.start = TimeFromSeconds(30);
  b.end = TimeFromSeconds(40);
  faults.faults = {a, b};
  // errors outside the outages (5 s, 25 s) are large and must not count
  const std::vector<ErrorSample> errors{
      At(5, 9, 9, 9),           At(10, 0.01, -0.05, 0.02), At(15, -0.08, 0.03, -0.10),
      At(20, 0.02, 0.04, 0.01), At(25, 9, 9, 9),           At(35, 0.0, -0.2, 0.3)};
  const auto o = ComputeOutages(errors, faults, 1.0);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_DOUBLE_EQ(o[0].max_abs_error_enu_m.x(), 0.08);
  EXPECT_DOUBLE_EQ(o[0].max_abs_error_enu_m.y(), 0.05);
  EXPECT_DOUBLE_EQ(o[0].max_abs_error_enu_m.z(), 0.10);
  EXPECT_DOUBLE_EQ(o[1].max_abs_error_enu_m.y(), 0.2);

  RunReport r;
  r.outages = o;
  const MetricTable t = RunMetricTable(r);
  EXPECT_DOUBLE_EQ(*t.at("outage_max_east_error_m"), 0.08);
  EXPECT_DOUBLE_EQ(*t.at("outage_max_north_error_m"), 0.2);
  EXPECT_DOUBLE_EQ(*t.at("outage_max_up_error_m"), 0.3);
  EXPECT_DOUBLE_EQ(*t.at("outage_max_enu_error_m"), 0.3);
  // no outage: the metrics cannot be computed (a criterion on them fails)
  EXPECT_FALSE(RunMetricTable(RunReport{}).at("outage_max_enu_error_m"));
}

}  // namespace
}  // namespace hil::harness

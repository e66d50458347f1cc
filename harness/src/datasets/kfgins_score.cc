#include "hil/harness/datasets/kfgins_score.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/angles.h"

namespace hil::harness {
namespace {

// north and east metres between two nearby geodetic points (WGS-84 meridian and prime-vertical
// radii at the first)
Eigen::Vector2d NorthEast(const KfginsNavLine& a, const KfginsNavLine& b) {
  constexpr double kA = 6378137.0, kE2 = 6.69437999014e-3;
  const double s = std::sin(a.lat_deg * kDeg);
  const double w = std::sqrt(1 - kE2 * s * s);
  const double rm = kA * (1 - kE2) / (w * w * w), rn = kA / w;
  return {(b.lat_deg - a.lat_deg) * kDeg * (rm + a.height_m),
          (b.lon_deg - a.lon_deg) * kDeg * (rn + a.height_m) * std::cos(a.lat_deg * kDeg)};
}

}  // namespace

KfginsScore ScoreKfginsNav(const std::vector<KfginsNavLine>& truth,
                           const std::vector<KfginsNavLine>& est, double from_s,
                           const std::vector<double>& outage_start_s, double outage_length_s) {
  if (truth.empty()) throw std::runtime_error("the truth file has no epochs");
  const double t0 = truth.front().sow;
  KfginsScore sc;
  sc.outage_max_h_m.assign(outage_start_s.size(), 0.0);
  double sum_h = 0, sum_v = 0;
  std::size_t j = 0;
  for (const KfginsNavLine& e : est) {
    while (j < truth.size() && truth[j].sow < e.sow - 1e-6) ++j;
    if (j == truth.size()) break;
    if (std::abs(truth[j].sow - e.sow) > 1e-6) continue;
    const double t = e.sow - t0;
    const double h = NorthEast(truth[j], e).norm();
    for (std::size_t k = 0; k < outage_start_s.size(); ++k) {
      if (t > outage_start_s[k] && t <= outage_start_s[k] + outage_length_s)
        sc.outage_max_h_m[k] = std::max(sc.outage_max_h_m[k], h);
    }
    if (t < from_s) continue;
    ++sc.epochs;
    sum_h += h * h;
    sum_v += (e.height_m - truth[j].height_m) * (e.height_m - truth[j].height_m);
    sc.max_h_m = std::max(sc.max_h_m, h);
  }
  if (sc.epochs == 0) throw std::runtime_error("no epoch of the result matches the truth");
  sc.rmse_h_m = std::sqrt(sum_h / static_cast<double>(sc.epochs));
  sc.rmse_v_m = std::sqrt(sum_v / static_cast<double>(sc.epochs));
  return sc;
}

}  // namespace hil::harness

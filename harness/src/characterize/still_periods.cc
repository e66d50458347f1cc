#include "hil/harness/characterize/still_periods.h"

#include <cmath>
#include <stdexcept>

namespace hil::harness {
namespace {

// true when every axis of both sensors varies less than its threshold within [first, first + n)
bool WindowStill(const UniformImu& u, std::size_t first, std::size_t n, const StillOptions& o) {
  Eigen::Vector3d gs = Eigen::Vector3d::Zero(), as = Eigen::Vector3d::Zero();
  Eigen::Vector3d gq = Eigen::Vector3d::Zero(), aq = Eigen::Vector3d::Zero();
  // deviations from the window's first cell keep the sums small (no cancellation)
  const Eigen::Vector3d g0 = u.gyro_radps[first], a0 = u.accel_mps2[first];
  for (std::size_t i = first; i < first + n; ++i) {
    const Eigen::Vector3d g = u.gyro_radps[i] - g0, a = u.accel_mps2[i] - a0;
    gs += g;
    as += a;
    gq += g.cwiseProduct(g);
    aq += a.cwiseProduct(a);
  }
  const double k = static_cast<double>(n);
  const Eigen::Vector3d gv = gq / k - (gs / k).cwiseProduct(gs / k);
  const Eigen::Vector3d av = aq / k - (as / k).cwiseProduct(as / k);
  return gv.maxCoeff() <= o.gyro_std_radps * o.gyro_std_radps &&
         av.maxCoeff() <= o.accel_std_mps2 * o.accel_std_mps2;
}

}  // namespace

std::vector<StillPeriod> FindStillPeriods(const UniformImu& u, const StillOptions& o) {
  const auto w = static_cast<std::size_t>(std::llround(o.window_s / u.step_s));
  if (w < 2) throw std::invalid_argument("still window shorter than two samples");
  const std::size_t windows = u.size() / w;
  std::vector<StillPeriod> out;
  std::size_t run_start = 0;
  for (std::size_t k = 0; k <= windows; ++k) {
    const bool still = k < windows && WindowStill(u, k * w, w, o);
    if (still) continue;
    // windows [run_start, k) were still: drop the first and the last (transitions)
    if (k >= run_start + 3) {
      StillPeriod p;
      p.first = (run_start + 1) * w;
      p.count = (k - run_start - 2) * w;
      p.from_s = static_cast<double>(p.first) * u.step_s;
      p.to_s = static_cast<double>(p.first + p.count) * u.step_s;
      if (p.to_s - p.from_s >= o.min_length_s) out.push_back(p);
    }
    run_start = k + 1;
  }
  return out;
}

}  // namespace hil::harness

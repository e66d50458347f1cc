#include "hil/estimator/innovation_monitor.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator {
namespace {
// standard normal quantiles of 2.5 % and 97.5 %
constexpr double kZ975 = 1.959963984540054;

// Wilson–Hilferty: χ²_p(k) ≈ k (1 − 2/(9k) + z_p √(2/(9k)))³
double ChiSquareQuantile(int dof, double z) {
  const double k = static_cast<double>(dof);
  const double a = 2.0 / (9.0 * k);
  const double c = 1.0 - a + z * std::sqrt(a);
  return k * std::max(0.0, c * c * c);
}
}  // namespace

ChiSquareBand ChiSquareMeanBand95(int dof) {
  if (dof <= 0) return {};
  const double k = static_cast<double>(dof);
  return {ChiSquareQuantile(dof, -kZ975) / k, ChiSquareQuantile(dof, kZ975) / k};
}

void InnovationMonitor::Record(double nis, int dof, bool accepted, double excess,
                               double clip_per_dof) {
  if (dof <= 0 || !std::isfinite(nis)) return;
  last_nis_ = nis;
  if (accepted) {
    ++accepted_;
    consecutive_rejected_ = 0;
  } else {
    ++rejected_;
    ++consecutive_rejected_;
  }
  if (count_ == kInnovationWindow) window_dof_ -= dof_[next_];
  nis_[next_] = std::min(nis, clip_per_dof * dof);
  excess_[next_] = std::isfinite(excess) ? std::clamp(excess, 0.0, clip_per_dof) : clip_per_dof;
  dof_[next_] = dof;
  window_dof_ += dof;
  next_ = (next_ + 1) % kInnovationWindow;
  count_ = std::min(count_ + 1, kInnovationWindow);
  if (count_ == kInnovationWindow) {
    if (window_above_band()) ++windows_above_;
    if (window_below_band()) ++windows_below_;
  }
}

void InnovationMonitor::ClearWindow() {
  next_ = 0;
  count_ = 0;
  window_dof_ = 0;
}

double InnovationMonitor::window_mean_nis_per_dof() const {
  if (window_dof_ <= 0) return 0.0;
  double sum = 0;
  for (int i = 0; i < count_; ++i) sum += nis_[i];
  return sum / static_cast<double>(window_dof_);
}

double InnovationMonitor::window_median_nis_per_dof() const {
  if (count_ == 0) return 0.0;
  std::array<double, kInnovationWindow> v{};
  for (int i = 0; i < count_; ++i) v[i] = nis_[i] / static_cast<double>(dof_[i]);
  const auto mid = v.begin() + count_ / 2;
  std::nth_element(v.begin(), mid, v.begin() + count_);
  return *mid;
}

double InnovationMonitor::window_mean_excess() const {
  if (count_ == 0) return 1.0;
  double sum = 0;
  for (int i = 0; i < count_; ++i) sum += excess_[i];
  return sum / static_cast<double>(count_);
}

bool InnovationMonitor::window_above_band() const {
  return count_ > 0 && window_mean_nis_per_dof() > window_band().high;
}

bool InnovationMonitor::window_below_band() const {
  return count_ > 0 && window_mean_nis_per_dof() < window_band().low;
}

}  // namespace hil::estimator

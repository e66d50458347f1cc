#pragma once
/// @file
/// Innovation monitoring of one aid source: the normalised innovation squared (NIS) of its last
/// `kInnovationWindow` updates, accepted or rejected, against the χ² band a consistent filter
/// keeps it in. Fixed size, no allocation.
///
/// For a consistent filter each update's NIS is χ²-distributed with the measurement's degrees of
/// freedom m, so the sum over a window of n updates is χ²(n·m). The window's mean NIS per degree of
/// freedom is compared with the two-sided 95 % band of χ²(n·m)/(n·m) (Bar-Shalom, Li and
/// Kirubarajan, "Estimation with Applications to Tracking and Navigation", 2001, §5.4: the
/// time-average NIS test). Quantiles from the Wilson–Hilferty approximation (Wilson and Hilferty
/// 1931), within 0.5 % of the exact quantiles from 30 degrees of freedom on.
/// Each update's NIS is clipped at `clip_per_dof` per degree of freedom before it enters the mean,
/// so one wild outlier cannot move the mean far (a persistent excess still does); the median is
/// there for a test that a few outliers cannot pass at all.

#include <array>
#include <cstdint>

namespace hil::estimator {

/// Updates in an innovation window.
inline constexpr int kInnovationWindow = 20;

/// Two-sided 95 % band of χ²(dof)/dof (Wilson–Hilferty).
struct ChiSquareBand {
  double low = 0, high = 0;
};
ChiSquareBand ChiSquareMeanBand95(int dof);

class InnovationMonitor {
 public:
  /// One update's NIS with its degrees of freedom; `excess` is the fading factor that would have
  /// made it consistent (ErrorStateEkf: (νᵀν − tr R) / tr(H P Hᵀ), ≥ 0).
  void Record(double nis, int dof, bool accepted, double excess, double clip_per_dof);
  /// Forgets the window (after the filter was adapted to it), keeps the totals.
  void ClearWindow();

  int window_count() const { return count_; }
  bool window_full() const { return count_ == kInnovationWindow; }
  /// Mean NIS per degree of freedom over the window (≈ 1 when consistent); 0 when empty.
  double window_mean_nis_per_dof() const;
  /// Median NIS per degree of freedom over the window (0 when empty): robust to a few outliers.
  double window_median_nis_per_dof() const;
  /// Mean of the excess factors over the window (1 when empty).
  double window_mean_excess() const;
  /// The 95 % band of the window's mean NIS per degree of freedom.
  ChiSquareBand window_band() const { return ChiSquareMeanBand95(window_dof_); }
  bool window_above_band() const;
  bool window_below_band() const;

  std::uint64_t accepted() const { return accepted_; }
  std::uint64_t rejected() const { return rejected_; }
  int consecutive_rejected() const { return consecutive_rejected_; }
  double last_nis() const { return last_nis_; }
  /// Windows found above / below their band (counted when the window is full).
  std::uint64_t windows_above() const { return windows_above_; }
  std::uint64_t windows_below() const { return windows_below_; }

 private:
  std::array<double, kInnovationWindow> nis_{};     // clipped NIS
  std::array<double, kInnovationWindow> excess_{};  // fading factors
  std::array<int, kInnovationWindow> dof_{};
  int next_ = 0, count_ = 0, window_dof_ = 0;
  std::uint64_t accepted_ = 0, rejected_ = 0, windows_above_ = 0, windows_below_ = 0;
  int consecutive_rejected_ = 0;
  double last_nis_ = 0;
};

}  // namespace hil::estimator

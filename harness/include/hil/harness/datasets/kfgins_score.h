#pragma once
/// @file
/// A KF-GINS-format result (.nav) scored against a truth .nav at the epochs both have: horizontal
/// RMSE from a start time on, the largest horizontal error, and the largest error inside each GNSS
/// outage window.

#include <cstddef>
#include <vector>

#include "hil/harness/datasets/kfgins_text.h"

namespace hil::harness {

struct KfginsScore {
  std::size_t epochs = 0;  ///< matched epochs scored (sow ≥ from)
  double rmse_h_m = 0, max_h_m = 0, rmse_v_m = 0;
  std::vector<double> outage_max_h_m;  ///< one per window
};

/// Times in seconds after the truth's first epoch. @throws std::runtime_error when no epoch
/// matches.
KfginsScore ScoreKfginsNav(const std::vector<KfginsNavLine>& truth,
                           const std::vector<KfginsNavLine>& estimate, double from_s,
                           const std::vector<double>& outage_start_s, double outage_length_s);

}  // namespace hil::harness

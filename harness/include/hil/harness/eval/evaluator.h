#pragma once
/// @file
/// Evaluation of an estimate against truth: each estimate is compared with the truth at its own
/// time of validity (never its arrival time), in the local ENU frame of the scenario origin.
/// The same accuracy metrics are computed for the raw GNSS fixes (the baseline).

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/sim_time.h"
#include "hil/harness/core/estimate_record.h"
#include "hil/harness/core/percentile.h"
#include "hil/harness/core/quantile_sketch.h"
#include "hil/harness/core/truth_table.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

/// The error of one record against truth, ENU.
struct ErrorSample {
  Time t{};
  Eigen::Vector3d err_enu_m = Eigen::Vector3d::Zero();
  std::optional<double> vel_err_mps;
  std::optional<double> yaw_err_deg;
  Eigen::Vector3d truth_enu_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d est_enu_m = Eigen::Vector3d::Zero();
  /// Cross-track error: signed distance of the estimate from the planned path minus that of the
  /// truth (see cross_track.h); set by AddCrossTrack.
  std::optional<double> xte_m;
  /// Normalised estimation error squared with the reported diagonal covariance (3 DOF).
  std::optional<double> nees;
  /// The same split by dimension: east and north (2 DOF), up (1 DOF); set with `nees`.
  std::optional<double> nees_horizontal, nees_vertical;
  double horizontal() const { return err_enu_m.head<2>().norm(); }
};

/// Accuracy metrics (report.json names).
struct AccuracyMetrics {
  std::size_t samples = 0;
  double horizontal_rmse_m = 0, cep50_m = 0, cep95_m = 0, max_horizontal_error_m = 0;
  double vertical_rmse_m = 0;
  std::optional<double> velocity_rmse_mps, heading_rmse_deg;
  std::optional<double> cross_track_rmse_m, cross_track_p95_m,
      cross_track_max_m;            ///< |xte| statistics
  std::optional<double> nees_mean;  ///< mean NEES (≈3 for a consistent 3-D position covariance)
  /// Mean NEES of the horizontal position (≈2 when consistent) and of the height (≈1).
  std::optional<double> nees_horizontal_mean, nees_vertical_mean;
};

/// Compares records with truth. `p_BX_B_m` is the lever arm of the point the records refer to
/// (zero for the estimator's reference point, the antenna's for raw fixes). Records before
/// `t_from` are skipped (convergence); records after `t_to` too.
std::vector<ErrorSample> CompareWithTruth(const truth::TruthConfig& truth_config,
                                          std::vector<EstimateRecord> records,
                                          const Eigen::Vector3d& p_BX_B_m, Time t_from, Time t_to);
/// The same with the truth from a table that holds every time RecordTimes(records, …) gives.
std::vector<ErrorSample> CompareWithTruth(const TruthTable& truth,
                                          std::vector<EstimateRecord> records,
                                          const Eigen::Vector3d& p_BX_B_m, Time t_from, Time t_to);
/// The error of one record against the truth sample at its time of validity (CompareWithTruth's
/// step; `frame`: the scenario's local frame).
ErrorSample ErrorOf(const EstimateRecord& r, const TruthSample& ts, const truth::LocalFrame& frame,
                    const Eigen::Vector3d& p_BX_B_m);
/// The times CompareWithTruth needs the truth at for `records`.
std::vector<Time> RecordTimes(const std::vector<EstimateRecord>& records, Time t_from, Time t_to);

/// The accuracy metrics of errors added one at a time, in time order, in bounded memory: running
/// sums (the same sums in the same order as over the whole set, so the same bits) and the
/// percentiles of QuantileSketch (exact up to its limit, then within its relative accuracy).
class AccuracyAccumulator {
 public:
  explicit AccuracyAccumulator(std::size_t exact_limit = QuantileSketch::kExactLimit)
      : horizontal_(exact_limit), abs_xte_(exact_limit) {}
  void Add(const ErrorSample& e);
  AccuracyMetrics Metrics() const;
  /// The horizontal errors so far (for the CDF plot).
  const QuantileSketch& horizontal() const { return horizontal_; }
  std::size_t retained() const { return horizontal_.retained() + abs_xte_.retained(); }

 private:
  std::size_t n_ = 0, nvel_ = 0, nyaw_ = 0, nnees_ = 0;
  double sh_ = 0, sv_ = 0, svel_ = 0, syaw_ = 0, max_h_ = 0;
  double sxte_ = 0, snees_ = 0, snees_h_ = 0, snees_v_ = 0;
  QuantileSketch horizontal_, abs_xte_;
};

/// Metrics of a set of errors (AccuracyAccumulator over them). Empty input gives samples = 0.
AccuracyMetrics ComputeAccuracy(const std::vector<ErrorSample>& errors);

}  // namespace hil::harness

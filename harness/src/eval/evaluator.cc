#include "hil/harness/eval/evaluator.h"

#include <algorithm>
#include <cmath>

namespace hil::harness {

std::vector<Time> RecordTimes(const std::vector<EstimateRecord>& records, Time t_from, Time t_to) {
  std::vector<Time> t;
  t.reserve(records.size());
  for (const EstimateRecord& r : records) {
    if (r.t_validity >= t_from && r.t_validity <= t_to && r.t_validity >= Time{})
      t.push_back(r.t_validity);
  }
  return t;
}

std::vector<ErrorSample> CompareWithTruth(const truth::TruthConfig& truth_config,
                                          std::vector<EstimateRecord> records,
                                          const Eigen::Vector3d& p_BX_B_m, Time t_from, Time t_to) {
  const TruthTable truth(truth_config, RecordTimes(records, t_from, t_to));
  return CompareWithTruth(truth, std::move(records), p_BX_B_m, t_from, t_to);
}

std::vector<ErrorSample> CompareWithTruth(const TruthTable& truth,
                                          std::vector<EstimateRecord> records,
                                          const Eigen::Vector3d& p_BX_B_m, Time t_from, Time t_to) {
  std::stable_sort(
      records.begin(), records.end(),
      [](const EstimateRecord& a, const EstimateRecord& b) { return a.t_validity < b.t_validity; });
  std::vector<ErrorSample> out;
  out.reserve(records.size());
  for (const EstimateRecord& r : records) {
    if (r.t_validity < t_from || r.t_validity > t_to || r.t_validity < Time{}) continue;
    out.push_back(ErrorOf(r, truth.At(r.t_validity), truth.frame(), p_BX_B_m));
  }
  return out;
}

ErrorSample ErrorOf(const EstimateRecord& r, const TruthSample& ts, const truth::LocalFrame& frame,
                    const Eigen::Vector3d& p_BX_B_m) {
  const Eigen::Matrix3d R_NB = ts.q_NB.toRotationMatrix();
  ErrorSample e;
  e.t = r.t_validity;
  e.truth_enu_m = ts.p_NB_N_m + R_NB * p_BX_B_m;
  e.est_enu_m = frame.FromGeodetic({r.lat_deg, r.lon_deg, r.height_m});
  e.err_enu_m = e.est_enu_m - e.truth_enu_m;
  if (r.vel_enu_mps) {
    const Eigen::Vector3d v_true = ts.v_NB_N_mps + R_NB * ts.w_NB_B_radps.cross(p_BX_B_m);
    e.vel_err_mps = (*r.vel_enu_mps - v_true).norm();
  }
  if (r.yaw_deg) {
    const Eigen::Vector3d fwd = R_NB.col(0);
    const double yaw_true = std::atan2(fwd.x(), fwd.y()) * 180.0 / M_PI;
    e.yaw_err_deg = std::fmod(*r.yaw_deg - yaw_true + 540.0, 360.0) - 180.0;
  }
  if (r.pos_std_enu_m && (r.pos_std_enu_m->array() > 0).all()) {
    const Eigen::Array3d z2 = (e.err_enu_m.array() / r.pos_std_enu_m->array()).square();
    e.nees = z2.sum();
    e.nees_horizontal = z2.x() + z2.y();
    e.nees_vertical = z2.z();
  }
  return e;
}

void AccuracyAccumulator::Add(const ErrorSample& e) {
  ++n_;
  const double he = e.horizontal();
  horizontal_.Add(he);
  sh_ += he * he;
  sv_ += e.err_enu_m.z() * e.err_enu_m.z();
  max_h_ = std::max(max_h_, he);
  if (e.vel_err_mps) {
    svel_ += *e.vel_err_mps * *e.vel_err_mps;
    ++nvel_;
  }
  if (e.yaw_err_deg) {
    syaw_ += *e.yaw_err_deg * *e.yaw_err_deg;
    ++nyaw_;
  }
  if (e.xte_m) {
    abs_xte_.Add(std::abs(*e.xte_m));
    sxte_ += *e.xte_m * *e.xte_m;
  }
  if (e.nees) {
    snees_ += *e.nees;
    snees_h_ += e.nees_horizontal.value_or(0.0);
    snees_v_ += e.nees_vertical.value_or(0.0);
    ++nnees_;
  }
}

AccuracyMetrics AccuracyAccumulator::Metrics() const {
  AccuracyMetrics m;
  m.samples = n_;
  if (n_ == 0) return m;
  const auto n = static_cast<double>(n_);
  m.max_horizontal_error_m = max_h_;
  m.horizontal_rmse_m = std::sqrt(sh_ / n);
  m.vertical_rmse_m = std::sqrt(sv_ / n);
  m.cep50_m = horizontal_.Percentile(50);
  m.cep95_m = horizontal_.Percentile(95);
  if (nvel_) m.velocity_rmse_mps = std::sqrt(svel_ / static_cast<double>(nvel_));
  if (nyaw_) m.heading_rmse_deg = std::sqrt(syaw_ / static_cast<double>(nyaw_));
  if (abs_xte_.count() > 0) {
    m.cross_track_rmse_m = std::sqrt(sxte_ / static_cast<double>(abs_xte_.count()));
    m.cross_track_p95_m = abs_xte_.Percentile(95);
    m.cross_track_max_m = abs_xte_.Percentile(100);
  }
  if (nnees_) {
    const auto n_nees = static_cast<double>(nnees_);
    m.nees_mean = snees_ / n_nees;
    m.nees_horizontal_mean = snees_h_ / n_nees;
    m.nees_vertical_mean = snees_v_ / n_nees;
  }
  return m;
}

AccuracyMetrics ComputeAccuracy(const std::vector<ErrorSample>& errors) {
  AccuracyAccumulator a;
  for (const ErrorSample& e : errors) a.Add(e);
  return a.Metrics();
}

}  // namespace hil::harness

#include "hil/harness/eval/evaluator.h"

#include <algorithm>
#include <cmath>

namespace hil::harness {

double Percentile(std::vector<double> v, double pct) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double pos = pct / 100.0 * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  const double f = pos - static_cast<double>(lo);
  return v[lo] * (1 - f) + v[hi] * f;
}

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
    const TruthSample& ts = truth.At(r.t_validity);
    const Eigen::Matrix3d R_NB = ts.q_NB.toRotationMatrix();
    ErrorSample e;
    e.t = r.t_validity;
    e.truth_enu_m = ts.p_NB_N_m + R_NB * p_BX_B_m;
    e.est_enu_m = truth.frame().FromGeodetic({r.lat_deg, r.lon_deg, r.height_m});
    e.err_enu_m = e.est_enu_m - e.truth_enu_m;
    if (r.vel_enu_mps) {
      const Eigen::Vector3d v_true = ts.v_NB_N_mps + R_NB * ts.w_NB_B_radps.cross(p_BX_B_m);
      e.vel_err_mps = (*r.vel_enu_mps - v_true).norm();
    }
    if (r.yaw_deg) {
      const Eigen::Vector3d fwd = R_NB.col(0);
      const double yaw_true = std::atan2(fwd.x(), fwd.y()) * 180.0 / M_PI;
      double d = std::fmod(*r.yaw_deg - yaw_true + 540.0, 360.0) - 180.0;
      e.yaw_err_deg = d;
    }
    if (r.pos_std_enu_m && (r.pos_std_enu_m->array() > 0).all()) {
      const Eigen::Array3d z2 = (e.err_enu_m.array() / r.pos_std_enu_m->array()).square();
      e.nees = z2.sum();
      e.nees_horizontal = z2.x() + z2.y();
      e.nees_vertical = z2.z();
    }
    out.push_back(e);
  }
  return out;
}

AccuracyMetrics ComputeAccuracy(const std::vector<ErrorSample>& errors) {
  AccuracyMetrics m;
  m.samples = errors.size();
  if (errors.empty()) return m;
  std::vector<double> h;
  double sh = 0, sv = 0, svel = 0, syaw = 0;
  std::size_t nvel = 0, nyaw = 0;
  for (const ErrorSample& e : errors) {
    const double he = e.horizontal();
    h.push_back(he);
    sh += he * he;
    sv += e.err_enu_m.z() * e.err_enu_m.z();
    m.max_horizontal_error_m = std::max(m.max_horizontal_error_m, he);
    if (e.vel_err_mps) {
      svel += *e.vel_err_mps * *e.vel_err_mps;
      ++nvel;
    }
    if (e.yaw_err_deg) {
      syaw += *e.yaw_err_deg * *e.yaw_err_deg;
      ++nyaw;
    }
  }
  const auto n = static_cast<double>(errors.size());
  m.horizontal_rmse_m = std::sqrt(sh / n);
  m.vertical_rmse_m = std::sqrt(sv / n);
  m.cep50_m = Percentile(h, 50);
  m.cep95_m = Percentile(h, 95);
  if (nvel) m.velocity_rmse_mps = std::sqrt(svel / static_cast<double>(nvel));
  if (nyaw) m.heading_rmse_deg = std::sqrt(syaw / static_cast<double>(nyaw));
  std::vector<double> xte;
  double sxte = 0, snees = 0, snees_h = 0, snees_v = 0;
  std::size_t nnees = 0;
  for (const ErrorSample& e : errors) {
    if (e.xte_m) {
      xte.push_back(std::abs(*e.xte_m));
      sxte += *e.xte_m * *e.xte_m;
    }
    if (e.nees) {
      snees += *e.nees;
      snees_h += e.nees_horizontal.value_or(0.0);
      snees_v += e.nees_vertical.value_or(0.0);
      ++nnees;
    }
  }
  if (!xte.empty()) {
    m.cross_track_rmse_m = std::sqrt(sxte / static_cast<double>(xte.size()));
    m.cross_track_p95_m = Percentile(xte, 95);
    m.cross_track_max_m = Percentile(xte, 100);
  }
  if (nnees) {
    const auto n_nees = static_cast<double>(nnees);
    m.nees_mean = snees / n_nees;
    m.nees_horizontal_mean = snees_h / n_nees;
    m.nees_vertical_mean = snees_v / n_nees;
  }
  return m;
}

}  // namespace hil::harness

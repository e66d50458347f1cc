#include "hil/estimator/uwb/tdoa_solver.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace hil::estimator::uwb {

const char* ToString(TdoaStatus s) {
  switch (s) {
    case TdoaStatus::kOk:
      return "ok";
    case TdoaStatus::kBadInput:
      return "bad_input";
    case TdoaStatus::kCollinearAnchors:
      return "collinear_anchors";
    case TdoaStatus::kOnBaseline:
      return "on_baseline";
    case TdoaStatus::kNoAdmissibleRoot:
      return "no_admissible_root";
  }
  return "unknown";
}

TdoaSolver::TdoaSolver(const TdoaSolverConfig& config) : config_(config) {
  const auto& bs = config_.p_W_anchor_m;
  for (const auto& p : bs) {
    if (!p.allFinite()) throw std::invalid_argument("TdoaSolver: anchor coordinate not finite");
  }
  Eigen::Matrix2d a;
  a.row(0) = (bs[1] - bs[0]).transpose();
  a.row(1) = (bs[2] - bs[0]).transpose();
  if (!(std::abs(a.determinant()) >= config_.min_det_m2)) {
    throw std::invalid_argument("TdoaSolver: BS1, BS2, BS3 are collinear (eq. 5 singular)");
  }
  p1_ = -a.inverse();
  const double k1 = bs[0].squaredNorm();
  k_diff_ = {bs[1].squaredNorm() - k1, bs[2].squaredNorm() - k1};
  for (int i = 0; i < 3; ++i) baseline_m_[i] = (bs[i + 1] - bs[0]).norm();
}

bool TdoaSolver::OnBaseline(const Eigen::Vector3d& r_i1_m) const {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(r_i1_m[i]) >= baseline_m_[i] - config_.baseline_margin_m) return true;
  }
  return false;
}

TdoaFix TdoaSolver::Solve(const Eigen::Vector3d& r_i1_m) const {
  TdoaFix fix;
  if (!r_i1_m.allFinite()) return fix;  // kBadInput
  if (OnBaseline(r_i1_m)) {
    fix.status = TdoaStatus::kOnBaseline;
    return fix;
  }
  const auto& bs = config_.p_W_anchor_m;
  // Eq. 5: p = P1·P2·r1 + P1·P3.
  const Eigen::Vector2d p2(r_i1_m[0], r_i1_m[1]);
  const Eigen::Vector2d p3 =
      -0.5 * Eigen::Vector2d(k_diff_[0] - p2[0] * p2[0], k_diff_[1] - p2[1] * p2[1]);
  const Eigen::Vector2d u = p1_ * p2;
  const Eigen::Vector2d w = p1_ * p3 - bs[0];
  // Eq. 6: a r1² + b r1 + m = 0.
  const double a = u.squaredNorm() - 1.0;
  const double b = 2.0 * u.dot(w);
  const double m = w.squaredNorm();
  double roots[2];
  int n_roots = 0;
  if (std::abs(a) < 1e-12) {
    if (std::abs(b) > 1e-12) roots[n_roots++] = -m / b;
  } else {
    double disc = b * b - 4.0 * a * m;
    if (disc < 0 && disc >= -config_.discriminant_slack * (b * b + 1.0)) disc = 0;
    if (disc >= 0) {
      // Numerically stable pair (no cancellation between −b and √disc).
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      roots[n_roots++] = q / a;
      if (q != 0) roots[n_roots++] = m / q;
    }
  }
  double best_residual = INFINITY;
  for (int k = 0; k < n_roots; ++k) {
    const double r1 = roots[k];
    if (!std::isfinite(r1) || r1 < 0) continue;
    if (r1 + r_i1_m[0] < 0 || r1 + r_i1_m[1] < 0 || r1 + r_i1_m[2] < 0) continue;
    const Eigen::Vector2d p = u * r1 + w + bs[0];
    const double residual = ((p - bs[3]).norm() - (p - bs[0]).norm()) - r_i1_m[2];
    ++fix.admissible_roots;
    if (std::abs(residual) < std::abs(best_residual)) {
      best_residual = residual;
      fix.p_W_m = p;
      fix.r1_m = r1;
    }
  }
  if (fix.admissible_roots == 0) {
    fix.status = TdoaStatus::kNoAdmissibleRoot;
    return fix;
  }
  fix.bs4_residual_m = best_residual;
  fix.status = TdoaStatus::kOk;
  return fix;
}

}  // namespace hil::estimator::uwb

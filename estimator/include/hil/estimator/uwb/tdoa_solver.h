#pragma once
/// @file
/// Paper 003's closed-form planar TDOA solution (seeds_001_003.md §B.4, eqs. 1–6) with four base
/// stations BS1–BS4 in the planar frame W (the paper's OXY, metres).
///
/// Inputs are the range differences r_i1 = r_i − r_1 = c·t_i1 (eq. 3) for i = 2, 3, 4. Eqs. 4–5 use
/// BS1–BS3 to express the tag as p = P1·P2·r_1 + P1·P3; eq. 6 (with P1P3 − X1, the extraction
/// "P1P3X1" corrected) gives a r_1² + b r_1 + m = 0. The paper states neither the root choice nor
/// the use of BS4; resolved here (vectors/uwb/README.md):
///  - a root is admissible when r_1 ≥ 0 and r_i = r_1 + r_i1 ≥ 0 for i = 2, 3, 4;
///  - among admissible roots, the one whose position best explains BS4's measured r_41 wins;
///  - a = 0 (tag direction along an asymptote) falls back to the linear root −m/b.
/// Degenerate geometry is flagged, never returned as NaN: BS1–BS3 collinear (eq. 5 singular), a
/// range difference at or beyond its baseline (the tag on a baseline's extension, where the
/// hyperbola collapses to a ray), non-finite input, or no admissible real root.
/// Fixed-size Eigen, no allocation.

#include <array>
#include <cstdint>

#include <Eigen/Core>

namespace hil::estimator::uwb {

/// Speed of light as the paper uses it (eq. 3), m/s.
inline constexpr double kPaperSpeedOfLight_mps = 3.0e8;

/// Range difference r_i1 (m) from an arrival-time difference t_i1 (s), eq. 3.
constexpr double RangeDifferenceFromTdoa_m(double t_i1_s) {
  return kPaperSpeedOfLight_mps * t_i1_s;
}

enum class TdoaStatus : std::uint8_t {
  kOk = 0,
  kBadInput,          ///< a non-finite range difference or anchor coordinate
  kCollinearAnchors,  ///< BS1, BS2, BS3 (nearly) collinear: eq. 5 has no inverse
  kOnBaseline,        ///< |r_i1| ≥ |BS_i − BS_1| − tolerance: the tag on a baseline extension
  kNoAdmissibleRoot,  ///< eq. 6 has no real root with non-negative ranges
};

const char* ToString(TdoaStatus s);

struct TdoaSolverConfig {
  std::array<Eigen::Vector2d, 4> p_W_anchor_m{};  ///< BS1–BS4 in W
  double baseline_margin_m = 0.01;  ///< |r_i1| within this of the baseline length is degenerate
  double min_det_m2 = 1e-3;         ///< |det| of eq. 5's matrix below this: collinear anchors
  /// A slightly negative discriminant (noise on a near-double root) down to −this·b² is taken as 0.
  double discriminant_slack = 1e-9;
};

struct TdoaFix {
  TdoaStatus status = TdoaStatus::kBadInput;
  Eigen::Vector2d p_W_m = Eigen::Vector2d::Zero();  ///< tag position; zero unless status == kOk
  double r1_m = 0;                                  ///< chosen root: range to BS1
  double bs4_residual_m = 0;  ///< predicted minus measured r_41 at the chosen position
  int admissible_roots = 0;   ///< 0, 1 or 2
  bool ok() const { return status == TdoaStatus::kOk; }
};

class TdoaSolver {
 public:
  /// @throws std::invalid_argument when BS1–BS3 are collinear or a coordinate is not finite.
  explicit TdoaSolver(const TdoaSolverConfig& config);
  /// r_i1_m = (r_21, r_31, r_41) in metres.
  TdoaFix Solve(const Eigen::Vector3d& r_i1_m) const;
  const TdoaSolverConfig& config() const { return config_; }

 private:
  bool OnBaseline(const Eigen::Vector3d& r_i1_m) const;
  TdoaSolverConfig config_;
  Eigen::Matrix2d p1_ = Eigen::Matrix2d::Zero();          ///< P1 = −[[x21, y21], [x31, y31]]⁻¹
  Eigen::Vector2d k_diff_ = Eigen::Vector2d::Zero();      ///< (K2 − K1, K3 − K1)
  Eigen::Vector3d baseline_m_ = Eigen::Vector3d::Zero();  ///< |BS_i − BS_1|, i = 2, 3, 4
};

}  // namespace hil::estimator::uwb

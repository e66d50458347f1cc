#pragma once
/// @file
/// Paper 003's cubic correction of UWB positions (seeds_001_003.md §B.5): eq. 7, the bivariate
/// cubic z(x, y) = m3x³ + m2x² + m1x + n3y³ + n2y² + n1y + p3x²y + p2xy² + p1xy + p0 fitted to the
/// grid errors, evaluated at the *measured* coordinates, and eq. 8, corrected = measured + z. Table
/// 1 holds the printed (rounded) coefficients. Coordinates in the paper's planar frame W (m).

#include <Eigen/Core>

namespace hil::estimator::uwb {

/// The ten coefficients of eq. 7 (metres, with x, y in metres).
struct CubicField {
  double m3 = 0, m2 = 0, m1 = 0, n3 = 0, n2 = 0, n1 = 0, p3 = 0, p2 = 0, p1 = 0, p0 = 0;
  /// z(x, y) in metres.
  double Evaluate_m(double x_m, double y_m) const {
    const double x2 = x_m * x_m, y2 = y_m * y_m;
    return m3 * x2 * x_m + m2 * x2 + m1 * x_m + n3 * y2 * y_m + n2 * y2 + n1 * y_m + p3 * x2 * y_m +
           p2 * x_m * y2 + p1 * x_m * y_m + p0;
  }
};

/// Table 1, z_X row.
inline constexpr CubicField kPaper003FieldX{0.00031, -0.00083,  -0.0384, -0.00007,  -0.00022,
                                            0.0016,  -0.000044, 0.00005, -0.000101, 0.0467};
/// Table 1, z_Y row.
inline constexpr CubicField kPaper003FieldY{0.00012, -0.00059, -0.0027, 0.00015,   0.00042,
                                            -0.0420, 0.000021, 0.00001, -0.000167, 0.0564};

struct ErrorFieldCorrection {
  CubicField z_x = kPaper003FieldX;
  CubicField z_y = kPaper003FieldY;
  /// The error (z_X, z_Y) at measured position p (m).
  Eigen::Vector2d Error_m(const Eigen::Vector2d& p_W_measured_m) const {
    return {z_x.Evaluate_m(p_W_measured_m.x(), p_W_measured_m.y()),
            z_y.Evaluate_m(p_W_measured_m.x(), p_W_measured_m.y())};
  }
  /// Eq. 8: corrected = measured + z(measured).
  Eigen::Vector2d Correct(const Eigen::Vector2d& p_W_measured_m) const {
    return p_W_measured_m + Error_m(p_W_measured_m);
  }
};

}  // namespace hil::estimator::uwb

#include "hil/truth/body_motion.h"

#include <array>
#include <numbers>

namespace hil::truth {
namespace {

using JVec = std::array<Jet2, 3>;
using JMat = std::array<JVec, 3>;  // row-major

JVec Cross(const JVec& a, const JVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

JVec Normalized(const JVec& a) {
  const Jet2 r = rsqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] * r, a[1] * r, a[2] * r};
}

JMat Mul(const JMat& a, const JMat& b) {
  JMat c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return c;
}

// the vibration's rotation, roll about x then pitch about y (body axes)
JMat RollPitch(const Jet2& roll, const Jet2& pitch) {
  const Jet2 cr = cos(roll), sr = sin(roll), cp = cos(pitch), sp = sin(pitch);
  // Rx(roll) · Ry(pitch)
  return JMat{JVec{cp, Jet2(0), sp}, JVec{sr * sp, cr, -(sr * cp)}, JVec{-(cr * sp), sr, cr * cp}};
}

Eigen::Vector3d VeeOfSkewPart(const Eigen::Matrix3d& m) {
  return 0.5 * Eigen::Vector3d(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

}  // namespace

BodyMotion CalcBodyMotion(const Terrain& terrain, const VibrationConfig& vibration,
                          const HorizontalJets& h, double t_s) {
  Jet2 z, ze, zn;
  terrain.Evaluate(h.e_m, h.n_m, z, ze, zn);
  const Jet2 c = cos(h.yaw_rad), s = sin(h.yaw_rad);
  // body axes on the surface: x along the heading's tangent, z the surface normal
  const JVec x = Normalized({c, s, ze * c + zn * s});
  const JVec zb = Normalized({-ze, -zn, Jet2(1.0)});
  const JVec y = Cross(zb, x);
  JMat R{JVec{x[0], y[0], zb[0]}, JVec{x[1], y[1], zb[1]}, JVec{x[2], y[2], zb[2]}};

  JVec p{h.e_m, h.n_m, z};
  if (!vibration.components.empty()) {
    Jet2 heave, roll, pitch;
    for (const VibrationComponent& v : vibration.components) {
      const double w = 2 * std::numbers::pi * v.frequency_hz;
      const Jet2 sn = sin(Jet2(w * t_s + v.phase_rad, w, 0));
      heave += v.heave_m * sn;
      roll += v.roll_rad * sn;
      pitch += v.pitch_rad * sn;
    }
    R = Mul(R, RollPitch(roll, pitch));
    for (int i = 0; i < 3; ++i) p[i] += heave * R[i][2];
  }

  BodyMotion m;
  Eigen::Matrix3d R1, R2;
  for (int i = 0; i < 3; ++i) {
    m.p_NB_N_m[i] = p[i].v;
    m.v_NB_N_mps[i] = p[i].d;
    m.a_NB_N_mps2[i] = p[i].dd;
    for (int j = 0; j < 3; ++j) {
      m.R_NB(i, j) = R[i][j].v;
      R1(i, j) = R[i][j].d;
      R2(i, j) = R[i][j].dd;
    }
  }
  // [ω]× = Rᵀ Ṙ and its derivative Ṙᵀ Ṙ + Rᵀ R̈
  m.w_NB_B_radps = VeeOfSkewPart(m.R_NB.transpose() * R1);
  m.alpha_NB_B_radps2 = VeeOfSkewPart(R1.transpose() * R1 + m.R_NB.transpose() * R2);
  return m;
}

}  // namespace hil::truth

#include "hil/estimator/mechanization.h"

#include <cmath>

namespace hil::estimator {
namespace {

constexpr double kMeanEarthRadius_m = 6371000.0;

}  // namespace

Eigen::Quaterniond QuatFromRotationVector(const Eigen::Vector3d& phi) {
  const double a = phi.norm();
  if (a < 1e-12)
    return Eigen::Quaterniond(1.0, 0.5 * phi.x(), 0.5 * phi.y(), 0.5 * phi.z()).normalized();
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, phi / a));
}

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

void Propagate(const EarthModel& earth, const Eigen::Vector3d& delta_angle_B_rad,
               const Eigen::Vector3d& delta_velocity_B_mps, double dt, MechanizationMemory& mem,
               NavState& s) {
  Eigen::Vector3d coning = Eigen::Vector3d::Zero(), sculling = Eigen::Vector3d::Zero();
  if (mem.valid) {
    coning = mem.prev_delta_angle_B_rad.cross(delta_angle_B_rad) / 12.0;
    sculling = (mem.prev_delta_angle_B_rad.cross(delta_velocity_B_mps) +
                mem.prev_delta_velocity_B_mps.cross(delta_angle_B_rad)) /
               12.0;
  }
  // velocity: specific force resolved with the attitude at the start, rotation and sculling terms
  const Eigen::Matrix3d C_old = s.q_NB.toRotationMatrix();
  // (I − ½[ζ×]) accounts for N turning with the Earth over the interval, ζ = ω_IE·dt
  const Eigen::Vector3d zeta = earth.w_IE_N_radps * dt;
  const Eigen::Vector3d dv_rot =
      C_old *
      (delta_velocity_B_mps + 0.5 * delta_angle_B_rad.cross(delta_velocity_B_mps) + sculling);
  const Eigen::Vector3d dv_N = dv_rot - 0.5 * zeta.cross(dv_rot);
  // gravity at the vehicle, not at the origin: in a tangent-plane frame the plumb line tilts by
  // p/R away from the origin and the magnitude falls by 2h/R (free-air gradient)
  const Eigen::Vector3d p_mid = s.p_N_m + 0.5 * s.v_N_mps * dt;
  const double g = -earth.g_N_mps2.z();
  Eigen::Vector3d accel_N =
      earth.g_N_mps2 +
      Eigen::Vector3d(-g * p_mid.x(), -g * p_mid.y(), 2.0 * g * p_mid.z()) / kMeanEarthRadius_m;
  if (earth.coriolis) accel_N -= 2.0 * earth.w_IE_N_radps.cross(s.v_N_mps);
  const Eigen::Vector3d v_old = s.v_N_mps;
  s.v_N_mps = v_old + dv_N + accel_N * dt;
  s.p_N_m += 0.5 * (v_old + s.v_N_mps) * dt;
  // attitude: body rotation, then the frame's rotation with the Earth
  s.q_NB = QuatFromRotationVector(-earth.w_IE_N_radps * dt) * s.q_NB *
           QuatFromRotationVector(delta_angle_B_rad + coning);
  s.q_NB.normalize();
  mem.prev_delta_angle_B_rad = delta_angle_B_rad;
  mem.prev_delta_velocity_B_mps = delta_velocity_B_mps;
  mem.valid = true;
}

}  // namespace hil::estimator

#include "hil/harness/datasets/imu_alignment.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hil::harness {

Eigen::Matrix3d NedFromFrd(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

double NormalGravity(double lat_deg, double height_m) {
  const double s2 = std::pow(std::sin(lat_deg * std::numbers::pi / 180), 2);
  return 9.7803267715 * (1 + 0.0052790414 * s2 + 0.0000232718 * s2 * s2) - 3.086e-6 * height_m;
}

namespace {

// the rest period: from the first IMU sample to the first GNSS epoch faster than the threshold,
// less one second
void FindRestSpan(const std::vector<TimedImuSample>& imu, const std::vector<CourseEpoch>& gnss,
                  const AlignmentOptions& o, ImuAlignment& a) {
  a.static_from_s = std::max(imu.front().t_s, gnss.front().t_s);
  a.static_to_s = gnss.back().t_s;
  for (const CourseEpoch& g : gnss)
    if (g.t_s >= a.static_from_s && g.v_ned_mps.norm() > o.rest_speed_mps) {
      a.static_to_s = g.t_s - 1.0;
      break;
    }
  if (a.static_to_s - a.static_from_s < o.min_rest_s)
    throw std::runtime_error("alignment: the log does not start with " +
                             std::to_string(o.min_rest_s) + " s at rest (GNSS speed below " +
                             std::to_string(o.rest_speed_mps) + " m/s)");
}

void LevelFromRest(const std::vector<TimedImuSample>& imu, const AlignmentOptions& o,
                   ImuAlignment& a) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
  int n = 0;
  for (const TimedImuSample& s : imu)
    if (s.t_s >= a.static_from_s && s.t_s <= a.static_to_s)
      f += s.f_frd_mps2, w += s.w_frd_radps, ++n;
  f /= n;
  a.f_static_frd_mps2 = f;
  a.gyro_bias_frd_radps = w / n;
  // at rest f = −C_bn g: f_z ≈ −g for a level FRD body
  a.roll_rad = std::atan2(-f.y(), -f.z());
  a.pitch_rad = std::atan2(f.x(), std::hypot(f.y(), f.z()));
  a.accel_bias_frd_mps2 = (f.norm() - o.normal_gravity_mps2) * f.normalized();
}

Eigen::Matrix3d RotationOf(const Eigen::Vector3d& angle) {
  const double n = angle.norm();
  return n > 0 ? Eigen::AngleAxisd(n, angle / n).toRotationMatrix() : Eigen::Matrix3d::Identity();
}

// velocity increments of the IMU (yaw 0) over one GNSS interval, attitude carried by the gyro
struct AlignStrapdown {
  Eigen::Matrix3d c;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
};

}  // namespace

ImuAlignment AlignImu(const std::vector<TimedImuSample>& imu, const std::vector<CourseEpoch>& gnss,
                      const AlignmentOptions& o) {
  ImuAlignment a;
  FindRestSpan(imu, gnss, o, a);
  LevelFromRest(imu, o, a);
  a.yaw_fit_from_s = a.static_to_s;
  a.yaw_fit_to_s = a.static_to_s + 1.0 + o.yaw_fit_s;
  // strapdown from the rest start, yaw 0: C(t) and v(t) at every GNSS epoch in the fit span
  AlignStrapdown sd{NedFromFrd(a.roll_rad, a.pitch_rad, 0)};
  const Eigen::Vector3d g(0, 0, o.normal_gravity_mps2);
  std::size_t i = 0, k = 0;
  while (i < imu.size() && imu[i].t_s < a.static_from_s) ++i;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> pairs;  // (IMU Δv, GNSS Δv)
  Eigen::Vector2d v_prev_imu = Eigen::Vector2d::Zero(), v_prev_gnss = Eigen::Vector2d::Zero();
  bool have_prev = false;
  double heading = 0, sum_c = 0, sum_s = 0;
  for (; i + 1 < imu.size() && k < gnss.size(); ++i) {
    const double dt = imu[i + 1].t_s - imu[i].t_s;
    const Eigen::Vector3d w =
        0.5 * (imu[i].w_frd_radps + imu[i + 1].w_frd_radps) - a.gyro_bias_frd_radps;
    const Eigen::Vector3d f =
        0.5 * (imu[i].f_frd_mps2 + imu[i + 1].f_frd_mps2) - a.accel_bias_frd_mps2;
    sd.v += (sd.c * RotationOf(0.5 * dt * w) * f + g) * dt;
    sd.c = sd.c * RotationOf(dt * w);
    while (k < gnss.size() && gnss[k].t_s <= imu[i + 1].t_s) {
      const CourseEpoch& e = gnss[k++];
      if (e.t_s < a.static_from_s) continue;
      heading = std::atan2(sd.c(1, 0), sd.c(0, 0));
      if (e.t_s <= a.yaw_fit_to_s) {
        if (have_prev)
          pairs.emplace_back(sd.v.head<2>() - v_prev_imu, e.v_ned_mps.head<2>() - v_prev_gnss);
        v_prev_imu = sd.v.head<2>(), v_prev_gnss = e.v_ned_mps.head<2>(), have_prev = true;
      }
      if (e.v_ned_mps.head<2>().norm() > o.motion_speed_mps) {
        const double course = std::atan2(e.v_ned_mps.y(), e.v_ned_mps.x());
        sum_c += std::cos(course - heading), sum_s += std::sin(course - heading);
        ++a.mount_yaw_epochs;
      }
    }
  }
  // yaw ψ rotates the IMU's horizontal increments onto the GNSS ones: ψ = arg Σ conj(a)·b
  double re = 0, im = 0;
  for (const auto& [u, v] : pairs) re += u.dot(v), im += u.x() * v.y() - u.y() * v.x();
  if (pairs.size() < 10 || std::hypot(re, im) == 0)
    throw std::runtime_error("alignment: too little GNSS after the rest to find the yaw");
  a.yaw_fit_intervals = pairs.size();
  a.yaw_rad = std::atan2(im, re);
  // headings above were with yaw 0: the mounting yaw is relative to the aligned heading
  a.mount_yaw_rad = std::remainder(std::atan2(sum_s, sum_c) - a.yaw_rad, 2 * std::numbers::pi);
  return a;
}

}  // namespace hil::harness

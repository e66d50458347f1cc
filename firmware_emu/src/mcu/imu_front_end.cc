#include "hil/firmware_emu/mcu/imu_front_end.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace hil::mcu {
namespace {

Biquad3 AntiAliasLowPass(double fc_hz, double fs_hz, const char* what) {
  if (!(fc_hz > 0 && fc_hz < 0.5 * fs_hz))
    throw std::invalid_argument(std::string("imu front end: ") + what +
                                " anti-alias cutoff must be in (0, internal_rate_hz / 2)");
  return Biquad3::ButterworthLowPass(fc_hz, fs_hz);
}

Eigen::Vector3d ClipToRange(const Eigen::Vector3d& v, double range) {
  return v.cwiseMax(-range).cwiseMin(range);
}

}  // namespace

double InterpolateProfile(const std::vector<ProfilePoint>& profile, double t_s, double fallback) {
  if (profile.empty()) return fallback;
  if (t_s <= profile.front().t_s) return profile.front().value;
  if (t_s >= profile.back().t_s) return profile.back().value;
  const auto it = std::upper_bound(profile.begin(), profile.end(), t_s,
                                   [](double t, const ProfilePoint& p) { return t < p.t_s; });
  const ProfilePoint& b = *it;
  const ProfilePoint& a = *(it - 1);
  const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
  return a.value + u * (b.value - a.value);
}

ImuFrontEnd::ImuFrontEnd(const RoughImuSpec& spec, const FrontEndLimits& limits, std::uint64_t seed)
    : spec_(spec),
      limits_(limits),
      vibration_(spec, seed),
      accel_aaf_(AntiAliasLowPass(limits.accel_aaf_hz, spec.internal_rate_hz, "accel")),
      gyro_aaf_(AntiAliasLowPass(limits.gyro_aaf_hz, spec.internal_rate_hz, "gyro")) {}

void ImuFrontEnd::Advance(Time t, const Eigen::Vector3d& f_I_mps2, const Eigen::Vector3d& w_I_radps,
                          Eigen::Vector3d& f_out, Eigen::Vector3d& w_out) {
  if (first_) {
    first_ = false;
    accel_aaf_.Settle(ClipToRange(f_I_mps2, limits_.accel_range_mps2));
    gyro_aaf_.Settle(ClipToRange(w_I_radps, limits_.gyro_range_radps));
    f_last_ = accel_aaf_.Step(ClipToRange(f_I_mps2, limits_.accel_range_mps2));
    w_last_ = gyro_aaf_.Step(ClipToRange(w_I_radps, limits_.gyro_range_radps));
  } else {
    const double span_s = ToSeconds(t - t_prev_);
    const long n = std::max(1L, std::lround(span_s * spec_.internal_rate_hz));
    const double h = span_s / static_cast<double>(n);
    vibration_.SetRpm(InterpolateProfile(spec_.rpm_profile, ToSeconds(t_prev_), 0), h);
    Eigen::Vector3d fv, wv;
    const double leak = std::exp(-h / kVibrationTiltLeakTau_s);
    for (long k = 1; k <= n; ++k) {
      const double u = static_cast<double>(k) / static_cast<double>(n);
      vibration_.Step(fv, wv);
      // the sensor turns by the vibration's own rate: its angle tilts the rigid body's specific
      // force (gravity included) into the sensor frame, f_S = f_I − θ × f_I (small angles)
      vib_angle_rad_ = leak * vib_angle_rad_ + wv * h;
      const Eigen::Vector3d f_rigid = f_prev_ + u * (f_I_mps2 - f_prev_);
      const Eigen::Vector3d f = f_rigid - vib_angle_rad_.cross(f_rigid) + fv;
      const Eigen::Vector3d w = w_prev_ + u * (w_I_radps - w_prev_) + wv;
      f_last_ = accel_aaf_.Step(ClipToRange(f, limits_.accel_range_mps2));
      w_last_ = gyro_aaf_.Step(ClipToRange(w, limits_.gyro_range_radps));
    }
  }
  t_prev_ = t;
  f_prev_ = f_I_mps2;
  w_prev_ = w_I_radps;
  f_out = f_last_;
  w_out = w_last_;
}

}  // namespace hil::mcu

#pragma once
// Drives a Device with an analytic truth (test helper): a vehicle turning at a constant rate with
// a small roll oscillation, sampled exactly at the device's event times.
#include <cmath>
#include <vector>

#include "hil/firmware_emu/device.h"

namespace hil::mcu::test {

/// Truth of a level vehicle turning left at `yaw_rate` with forward speed `speed`, optionally
/// rocking about x with amplitude `roll_amp_rad` at `roll_hz`.
inline TruthSample AnalyticTruth(Time t, double speed = 0.45, double yaw_rate = 0.1,
                                 double roll_amp_rad = 0.0, double roll_hz = 0.5) {
  const double s = ToSeconds(t);
  TruthSample x;
  x.t = t;
  const double yaw = yaw_rate * s;
  const double w_roll = 2 * 3.141592653589793 * roll_hz;
  const double roll = roll_amp_rad * std::sin(w_roll * s);
  x.q_NB = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
           Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  const double roll_rate = roll_amp_rad * w_roll * std::cos(w_roll * s);
  // body rates: yaw about N's z seen in B, plus the roll rate
  x.w_NB_B_radps =
      x.q_NB.conjugate() * Eigen::Vector3d(0, 0, yaw_rate) + Eigen::Vector3d(roll_rate, 0, 0);
  x.w_IB_B_radps = x.w_NB_B_radps;
  x.alpha_NB_B_radps2 =
      Eigen::Vector3d(-roll_amp_rad * w_roll * w_roll * std::sin(w_roll * s), 0, 0);
  x.v_NB_N_mps = Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0) * speed;
  x.a_NB_N_mps2 = Eigen::Vector3d(-std::sin(yaw), std::cos(yaw), 0) * speed * yaw_rate;
  x.f_B_mps2 = x.q_NB.conjugate() * (x.a_NB_N_mps2 - x.gravity_N_mps2);
  x.speed_mps = speed;
  return x;
}

/// Runs `dev` until `t_end` and collects everything it sends.
template <class Dev>
DeviceOutput RunDevice(Dev& dev, Time t_end, double roll_amp_rad = 0.0) {
  DeviceOutput all, step;
  while (dev.next_event_time() < t_end) {
    step.clear();
    dev.OnEvent(AnalyticTruth(dev.next_event_time(), 0.45, 0.1, roll_amp_rad), step);
    all.serial.insert(all.serial.end(), step.serial.begin(), step.serial.end());
    all.can.insert(all.can.end(), step.can.begin(), step.can.end());
  }
  return all;
}

}  // namespace hil::mcu::test

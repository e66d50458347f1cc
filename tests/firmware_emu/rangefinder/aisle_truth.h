#pragma once
// Analytic truth for the range-sensor tests: the vehicle drives east along aisle 0 of a small
// greenhouse (rows run east from (0, 0), 1.8 m apart, 0.6 m wide: aisle 0's centre line is
// y = 0.9) at a constant speed, weaving gently (lateral and yaw sines); and a runner that feeds a
// device at its event times and delivers host commands between events.
#include <cmath>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/world/greenhouse_world.h"

namespace hil::test {

inline world::GreenhouseConfig SmallGreenhouse() {
  world::GreenhouseConfig c;
  c.row_direction_deg = 0;
  c.ridge_count = 3;
  c.ridge_width_m = 0.6;
  c.ridge_height_m = 0.3;
  c.ridge_spacing_m = 1.8;
  c.ridge_length_m = 20;
  c.headland_m = 3;
  c.side_margin_m = 1.5;
  c.post_spacing_m = 4;
  return c;
}

struct AisleTruth {
  double x0_m = -0.5, speed_mps = 0.3, lateral_amp_m = 0.05, yaw_amp_deg = 2, weave_hz = 0.25;
  TruthSample At(Time t) const {
    const double s = ToSeconds(t), w = 2 * 3.14159265358979323846 * weave_hz;
    TruthSample x;
    x.t = t;
    x.p_NB_N_m = Eigen::Vector3d(x0_m + speed_mps * s, 0.9 + lateral_amp_m * std::sin(w * s), 0);
    const double yaw = yaw_amp_deg * 3.14159265358979323846 / 180 * std::sin(w * s);
    x.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
    x.speed_mps = speed_mps;
    return x;
  }
};

struct HostCommand {
  Time t;
  std::string bytes;
};

/// Every message of `dev` until `t_end`, with `cmds` (ascending) delivered between events;
/// `after_event` sees the device after each of its events (e.g. to record its last reading).
template <class Dev, class Fn>
std::vector<SerialMessage> RunDevice(Dev& dev, const AisleTruth& truth, Time t_end,
                                     const std::vector<HostCommand>& cmds, Fn after_event) {
  std::vector<SerialMessage> sent;
  std::size_t next_cmd = 0;
  DeviceOutput out;
  for (;;) {
    const Time te = dev.next_event_time();
    if (next_cmd < cmds.size() && cmds[next_cmd].t <= te && cmds[next_cmd].t <= t_end) {
      dev.OnHostBytes(0, cmds[next_cmd].t, cmds[next_cmd].bytes, out);
      ++next_cmd;
      for (auto& m : out.serial) sent.push_back(m), after_event(m, false);
      out.clear();
      continue;
    }
    if (te > t_end) break;
    dev.OnEvent(truth.At(te), out);
    for (auto& m : out.serial) sent.push_back(m), after_event(m, true);
    out.clear();
  }
  return sent;
}

}  // namespace hil::test

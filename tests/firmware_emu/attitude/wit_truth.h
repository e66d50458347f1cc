#pragma once
// Analytic truth for the WT901C tests: a vehicle turning left at a constant rate from a start yaw,
// rocking about x (sine), level otherwise; and a runner that feeds a device at its event times.
#include <cmath>
#include <numbers>
#include <vector>

#include "hil/firmware_emu/attitude/wt901c_device.h"

namespace hil::wit::test {

inline constexpr double kDegToRad = std::numbers::pi / 180.0;

struct TurnTruth {
  double yaw0_deg = 170.0, yaw_rate_dps = 20.0, roll_amp_deg = 2.0, roll_hz = 0.5;
  TruthSample At(Time t) const {
    const double s = ToSeconds(t);
    const double w_roll = 2 * std::numbers::pi * roll_hz;
    const double yaw = (yaw0_deg + yaw_rate_dps * s) * kDegToRad;
    const double roll = roll_amp_deg * kDegToRad * std::sin(w_roll * s);
    TruthSample x;
    x.t = t;
    x.q_NB = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
             Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
    const double roll_rate = roll_amp_deg * kDegToRad * w_roll * std::cos(w_roll * s);
    x.w_NB_B_radps = x.q_NB.conjugate() * Eigen::Vector3d(0, 0, yaw_rate_dps * kDegToRad) +
                     Eigen::Vector3d(roll_rate, 0, 0);
    x.w_IB_B_radps = x.w_NB_B_radps;
    x.f_B_mps2 = x.q_NB.conjugate() * (-x.gravity_N_mps2);
    return x;
  }
};

/// A host command arriving at `t`.
struct HostCommand {
  Time t;
  std::string bytes;
};

/// One message with the continuous values of the cycle that produced it (zero for replies).
struct Sent {
  SerialMessage msg;
  Wt901cCycle cycle;
};

/// Runs `dev` until `t_end`, delivering `cmds` (ascending) between events at their times.
inline std::vector<Sent> Run(Wt901cDevice& dev, const TurnTruth& truth, Time t_end,
                             const std::vector<HostCommand>& cmds = {}) {
  std::vector<Sent> sent;
  std::size_t next_cmd = 0;
  DeviceOutput out;
  auto collect = [&](const Wt901cCycle& c) {
    for (auto& m : out.serial) sent.push_back({m, c});
    out.clear();
  };
  for (;;) {
    const Time te = dev.next_event_time();
    if (next_cmd < cmds.size() && cmds[next_cmd].t <= te && cmds[next_cmd].t <= t_end) {
      dev.OnHostBytes(0, cmds[next_cmd].t, cmds[next_cmd].bytes, out);
      ++next_cmd;
      collect(Wt901cCycle{});
      continue;
    }
    if (te > t_end) break;
    dev.OnEvent(truth.At(te), out);
    collect(dev.last_cycle());
  }
  return sent;
}

}  // namespace hil::wit::test

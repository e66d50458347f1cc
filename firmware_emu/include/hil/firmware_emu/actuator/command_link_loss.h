#pragma once
// A command link's loss windows (fault command_link_loss: a cut serial cable, a broken CAN stub):
// what the controller sends while a window is open never reaches the actuator. Counts what each
// window cut, in the windows' order (the fault record notes each; their sum is the run's total).
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "hil/firmware_emu/sim_time.h"

namespace hil::actuator {

class CommandLinkLoss {
 public:
  /// `windows`: [first, second) of emulated arrival time, each a loss.
  explicit CommandLinkLoss(std::vector<std::pair<Time, Time>> windows)
      : windows_(std::move(windows)), lost_(windows_.size(), 0) {}

  /// Whether a window is open at `t`; if so, `units` (bytes or frames) count against it.
  bool Cuts(Time t, std::uint64_t units) {
    for (std::size_t i = 0; i < windows_.size(); ++i) {
      if (t >= windows_[i].first && t < windows_[i].second) {
        lost_[i] += units;
        return true;
      }
    }
    return false;
  }
  /// What each window cut, in the windows' order.
  const std::vector<std::uint64_t>& per_window() const { return lost_; }
  /// What all windows cut.
  std::uint64_t total() const {
    return std::accumulate(lost_.begin(), lost_.end(), std::uint64_t{0});
  }

 private:
  std::vector<std::pair<Time, Time>> windows_;
  std::vector<std::uint64_t> lost_;
};

}  // namespace hil::actuator

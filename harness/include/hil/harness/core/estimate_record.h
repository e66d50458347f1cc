#pragma once
/// @file
/// One solution of the estimator under test (or one raw GNSS fix) as the harness reads it back:
/// what the output readers (dut/) produce and the evaluation (eval/) compares with the truth.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {

/// One solution of the estimator under test (or one raw GNSS fix), as read back.
struct EstimateRecord {
  Time t_validity{};
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  std::optional<Eigen::Vector3d> vel_enu_mps;
  std::optional<double> yaw_deg;  ///< heading clockwise from north
  std::optional<Eigen::Vector3d>
      pos_std_enu_m;   ///< reported 1-sigma position uncertainty (for NEES)
  WallTime wall_rx{};  ///< arrival (the clock's epoch when not applicable)
};

}  // namespace hil::harness

#pragma once
/// @file
/// Which receiver navd reads in a scenario, and so which fixes the raw-fix baseline scores: the
/// `gnss` receivers (NEO-5M or the `rtk` profile) or the ZED-F9P rover (`zed_f9p:`). The rule
/// (vectors/scenarios/README.md, "RTK rover"): a scenario with a `zed_f9p` section feeds navd
/// from the rover, unless it says `zed_f9p.navd_input: false`; navd then reads the rover's NMEA
/// (GGA quality 4/5 with navd's RTK σ's) instead of the first `gnss` receiver, never both.
/// navd's UWB and gyro-odometry modes read no GNSS receiver; its multi_gnss mode reads the
/// `gnss` receivers only (the scenario loader refuses it with a rover that feeds navd).

#include <Eigen/Core>

#include "hil/harness/scenario/scenario.h"

namespace hil::harness {

/// Whether the scenario's navd reads the ZED-F9P rover instead of the `gnss` receivers.
bool NavdReadsRover(const Scenario& s);

/// The antenna (body frame [forward, left, up], m) of the receiver navd reads and whose fixes
/// are the raw-fix baseline: the rover's when NavdReadsRover, else the first `gnss` receiver's.
Eigen::Vector3d NavdAntennaB(const Scenario& s);

}  // namespace hil::harness

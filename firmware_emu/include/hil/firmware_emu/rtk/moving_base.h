#pragma once
/// @file
/// @system
/// name: MovingBase (the moving-base receiver of a dual-antenna heading set: a second ZED-F9P on
///       the vehicle, its UART2 wired to the rover's UART2)
/// input: TruthSample at each of its epochs (the rover's navigation epochs)
/// output: per epoch, RTCM 3 frames ready `output_lag` after the epoch: 4072.0 (its antenna
///         position, rtcm3_moving_base.h) then the GPS MSM of its observations
/// rate: the rover's navigation rate (a moving base and its rover run at the same rate)
/// @endsystem
///
/// Layers: truth + lever arm → antenna position → BaseObservables (moved each epoch) → MsmEpoch
/// → rtcm3_msm / rtcm3_moving_base bodies → rtcm3_frame. The rover (ZedF9pDevice) times the
/// bytes on the wire at `baud`. The 4072.0 position is the antenna's truth (the moving base's
/// own standalone error does not enter the rover's baseline, which the carrier phases give).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/rtk/base_observables.h"
#include "hil/firmware_emu/rtk/rtcm3_msm.h"
#include "hil/firmware_emu/unix_time.h"

namespace hil::rtk {

struct MovingBaseConfig {
  int station_id = 0;  ///< DF003 of its 4072.0 and MSM (the F9P's default reference ID, 0)
  /// Its antenna in the body frame [forward, left, up] (m).
  Eigen::Vector3d p_BA_B_m = Eigen::Vector3d::Zero();
  rtcm3::MsmKind msm = rtcm3::MsmKind::kMsm7;
  /// Epoch → first byte on its UART2: 30 ms of computation, as RtkBaseConfig (ours).
  Duration output_lag = std::chrono::milliseconds(30);
  /// The wire between the two UART2s: 460800 Bd (ours: the integration manual asks for a rate
  /// that carries the moving base's RTCM within the epoch; 38400 Bd does not at 5 Hz).
  int baud = 460800;
  BaseObservablesConfig observables;
};

/// The antenna of a body at `truth` with lever arm `p_BA_B_m`: ECEF and geodetic (small offsets
/// on the ellipsoid's local radii).
struct AntennaPosition {
  Eigen::Vector3d p_E_m = Eigen::Vector3d::Zero();
  double lat_deg = 0, lon_deg = 0, height_m = 0;
};
AntennaPosition AntennaAt(const TruthSample& truth, const Eigen::Vector3d& p_BA_B_m);

class MovingBase {
 public:
  MovingBase(const MovingBaseConfig& config, UnixTime start_utc, std::uint64_t seed);
  /// The frames of the epoch at `truth.t`, ready at t + output_lag (4072.0 first, then the MSM).
  std::vector<SerialMessage> Epoch(const TruthSample& truth);
  const MovingBaseConfig& config() const { return config_; }

 private:
  MovingBaseConfig config_;
  UnixTime start_utc_{};
  gnss::Constellation constellation_;
  BaseObservables observables_;
};

}  // namespace hil::rtk

#pragma once
/// @file
/// The estimator core's inputs as value types, time-stamped on one time base (GpsTime,
/// time_types.h), already mapped from each device's own clock by the drivers. Frames: N = ENU at
/// the filter origin, B = body FLU (x forward, y left, z up).

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/geodesy.h"
#include "hil/estimator/time_types.h"

namespace hil::estimator {

/// One IMU interval: increments over (t − dt, t].
struct ImuSample {
  GpsTime t{};                                                     ///< end of the interval
  double dt_s = 0;                                                 ///< interval length
  Eigen::Vector3d delta_angle_B_rad = Eigen::Vector3d::Zero();     ///< ∫ ω_IB_B dt
  Eigen::Vector3d delta_velocity_B_mps = Eigen::Vector3d::Zero();  ///< ∫ f_B dt
};

/// One GNSS fix of the antenna, time of validity t (the receiver's measurement epoch).
struct GnssSample {
  GpsTime t{};
  Lla position;                                  ///< antenna, WGS-84
  Eigen::Vector3d pos_std_enu_m{1.0, 1.0, 2.0};  ///< 1σ per ENU axis
  int fix_dim = 3;  ///< 3: 3-D fix; 2: 2-D fix (height held by the receiver, not measured)
  bool has_velocity = false;  ///< the velocity vector is known (speed and direction)
  Eigen::Vector3d vel_enu_mps = Eigen::Vector3d::Zero();  ///< antenna velocity
  Eigen::Vector3d vel_std_enu_mps{0.2, 0.2, 0.4};
  /// vel_std_enu_mps is a configured figure (NMEA has no velocity accuracy), not the receiver's own
  /// estimate: the navigator may learn a smaller one from the innovations (GnssVelocityNoise)
  bool vel_std_configured = false;
  /// Horizontal speed over ground when the receiver reports it, also when its direction is
  /// unknown (e.g. an RMC with an empty course field): reported, never fused as a velocity.
  std::optional<double> ground_speed_mps;
  int num_sv = 0;
  int fix_quality = 1;  ///< 0 none, 1 GPS, 2 DGPS, 4/5 RTK
  double hdop = 0;      ///< receiver's HDOP (0: not reported)
  double vdop = 0;      ///< receiver's VDOP (NMEA GSA; 0: not reported)
  /// the receiver's geoid height above the ellipsoid (GGA field 11, UBX height − hMSL), when it
  /// says; position.height_m is ellipsoidal either way
  std::optional<double> geoid_separation_m;
  /// σ of an error common to the heights of every fix, which no fix reveals and the filter cannot
  /// estimate: an NMEA altitude's geoid separation rounded to its step (0: none). The navigator
  /// adds its variance to the reported height σ.
  double height_datum_std_m = 0;
  int antenna = 0;  ///< receiver index (multi-receiver)
  /// The receiver's own horizontal 1σ per axis when it reports one (UBX NAV-PVT hAcc / √2, before
  /// navd's scale and floor); 0: not reported (NMEA). An RTK float solution's error is correlated
  /// over many epochs: the navigator sizes its float error model by it.
  double receiver_h_std_m = 0;
};

/// A magnetometer heading (already tilt-compensated and declination-corrected).
struct HeadingSample {
  GpsTime t{};
  double yaw_deg = 0;  ///< clockwise from true north
  double std_deg = 5.0;
};

}  // namespace hil::estimator

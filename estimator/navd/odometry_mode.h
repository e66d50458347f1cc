#pragma once
// navd's gyro + wheel-odometry mode (paper 001): the MCU IMU and the base's encoder sentences
// ([odometry], navd_odometry_config.h) into GyroOdometryNavigator; JSON lines and NMEA out.
#include <csignal>
#include <cstdio>

#include "hil/estimator/navd/navd_config.h"

namespace hil::navd {

/// Runs until *stop is set; one solution per [output] rate_hz period of IMU time to `out` (JSON)
/// and to `nmea_fd` (GGA, RMC, HDT; −1: none); its counters to stderr when it stops.
int RunOdometryMode(const estimator::NavdConfig& cfg, std::FILE* out, int nmea_fd,
                    volatile std::sig_atomic_t* stop);

}  // namespace hil::navd

#pragma once
// navd's UWB mode (paper 003): the [uwb] section's devices into the planar filter, JSON lines out
// (and NMEA 0183 to [output] nmea_device, for a guidance controller).
#include <csignal>
#include <cstdio>

#include "hil/estimator/navd/navd_config.h"

namespace hil::navd {

/// Runs until *stop is set; writes one JSON solution line per UWB fix to `out` (and, when
/// `nmea_fd` ≥ 0, its GNRMC, GNGGA and GNHDT sentences there) and its counters to stderr when it
/// stops. Returns navd's exit code.
int RunUwbMode(const estimator::NavdConfig& cfg, std::FILE* out, int nmea_fd,
               volatile std::sig_atomic_t* stop);

}  // namespace hil::navd

#pragma once
// navd's UWB mode (paper 003): the [uwb] section's devices into the planar filter, JSON lines out.
#include <csignal>
#include <cstdio>

#include "hil/estimator/navd/navd_config.h"

namespace hil::navd {

/// Runs until *stop is set; writes one JSON solution line per UWB fix to `out` and its counters to
/// stderr when it stops. Returns navd's exit code.
int RunUwbMode(const estimator::NavdConfig& cfg, std::FILE* out, volatile std::sig_atomic_t* stop);

}  // namespace hil::navd

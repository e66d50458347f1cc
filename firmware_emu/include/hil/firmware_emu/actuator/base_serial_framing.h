#pragma once
/// @file
/// Framing layer of the differential-drive base's serial protocol (ROSArduinoBridge, see
/// vectors/base_serial/README.md): commands are ASCII lines terminated by CR (13). LF is ignored
/// (a host that ends lines with CR LF works as on the real firmware). A line longer than
/// `kMaxBaseLineLength` is discarded up to its CR and counted. The framer is the one the SLCAN
/// adapter uses: link::CrLineFramer.

#include <cstddef>

#include "hil/firmware_emu/link/cr_line_framer.h"

namespace hil::actuator {

inline constexpr std::size_t kMaxBaseLineLength = 32;

}  // namespace hil::actuator

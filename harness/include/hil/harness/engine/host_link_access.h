#pragma once
/// @file
/// How the programs under test hold hil's links, from /proc (their descriptors and the flags
/// they were opened with): what the lockstep lookahead (lookahead_writer.h) needs to know before
/// it writes ahead.

#include <vector>

#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {

/// Whether the processes `pids` between them hold every one of `links` open (its host side), and
/// none of them for writing. False when /proc cannot say.
bool LinksHeldReadOnly(const std::vector<int>& pids, const std::vector<SerialEndpoint*>& links);

}  // namespace hil::harness

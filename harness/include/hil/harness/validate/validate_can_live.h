#pragma once
/// @file
/// `hil validate --protocol can IFACE`: listening to a live SocketCAN interface (vcan0, can0) for a
/// while, so the candump-log checks (validate_can.cc) run on what is on the bus now. Frames are
/// turned into `candump -l` lines with their kernel receive times.

#include <cstdint>
#include <string>

#include "hil/harness/validate/validate.h"

namespace hil::harness {

/// True when `source` names a network interface rather than a file: no file of that name exists
/// and /sys/class/net/<source> does.
bool IsNetworkInterface(const std::string& source);

/// What a live listen saw.
struct CanListen {
  std::string candump_text;  ///< one `candump -l` line per frame
  std::uint64_t frames = 0, rx_queue_drops = 0, error_frames = 0;
};

/// Listens to `iface` for `listen_s` seconds. @throws std::runtime_error when it cannot be opened
/// (the message names the interface; on a kernel without CAN it points at ci/vcan/run_in_vm).
CanListen ListenCanInterface(const std::string& iface, double listen_s);

/// Listens, then checks the frames as a candump log; frames the receive queue dropped are an
/// error finding (the check saw less than the bus carried), and so is a silent bus.
ValidationReport ValidateCanInterface(const std::string& iface, double listen_s);

}  // namespace hil::harness

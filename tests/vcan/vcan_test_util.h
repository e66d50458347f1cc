#pragma once
// Shared by the tests that run on a real vcan0 (in the VM of ci/vcan/run_in_vm, or on a host with
// vcan). They fail, never skip, when the interface is missing: ctest only starts them where vcan0
// exists, and a CAN test must never pass without frames crossing a bus.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/socketcan_port.h"

namespace hil::link::test {

/// The interface under test: $HIL_CAN_IFACE or vcan0.
inline std::string Iface() {
  const char* e = std::getenv("HIL_CAN_IFACE");
  return e && *e ? e : "vcan0";
}

/// Receives until `n` non-error frames came or `timeout` passed.
inline std::vector<ReceivedCanFrame> ReceiveFrames(SocketCanPort& port, std::size_t n,
                                                   Duration timeout) {
  std::vector<ReceivedCanFrame> out;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (out.size() < n && std::chrono::steady_clock::now() < deadline) {
    if (auto r = port.Receive(std::chrono::milliseconds(50)); r && !r->frame.error)
      out.push_back(*r);
  }
  return out;
}

}  // namespace hil::link::test

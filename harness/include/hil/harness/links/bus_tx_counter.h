#pragma once
/// @file
/// How many frames were sent on a virtual CAN interface (vcan) since the counter was made: the
/// kernel's `tx_packets` statistic of the interface (/sys/class/net/IF/statistics/tx_packets),
/// which a frame's send(2) raises before it returns, while its copies reach the other sockets
/// later (the CAN core loops them back through netif_rx, delivered in a softirq). A host that is
/// idle has therefore raised the counter for every frame it wrote, and a reader that received as
/// many frames has them all. Only for an interface of this machine (/sys/devices/virtual/net/IF):
/// on a real bus, frames of other nodes are not counted by tx_packets.

#include <cstdint>
#include <optional>
#include <string>

namespace hil::harness {

class BusTxCounter {
 public:
  /// `sysfs` is the sysfs root (tests give a tree of their own).
  explicit BusTxCounter(const std::string& iface, const std::string& sysfs = "/sys");
  /// Whether the interface is virtual and its counter readable.
  bool available() const { return base_.has_value(); }
  /// Frames sent on the interface since construction (nullopt when not available or unreadable).
  std::optional<std::uint64_t> SentSinceStart() const;

 private:
  std::optional<std::uint64_t> Read() const;
  std::string path_;
  std::optional<std::uint64_t> base_;
};

}  // namespace hil::harness

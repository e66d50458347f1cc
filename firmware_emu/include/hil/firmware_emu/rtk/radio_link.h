#pragma once
/// @file
/// A correction radio (a UHF or 868/915 MHz modem pair) between a base and a rover's UART: each
/// packet the base hands it leaves after the previous one has gone (the air byte rate), arrives
/// `latency` after its last byte has been sent, or is lost (seeded Bernoulli losses, and scripted
/// outages during which nothing arrives). Deterministic: the same seed, the same losses.

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "hil/firmware_emu/sim_time.h"

namespace hil::rtk {

struct RadioOutage {
  Time start{}, end{};  ///< nothing arrives for start ≤ t_sent < end
};

struct RadioLinkConfig {
  /// Air throughput (bytes/s): 960 B/s is a 9600 bit/s air rate with 8N1-like overhead, the
  /// lowest setting of the common 430–470 MHz modems (ours; a source would give the modem's).
  double bytes_per_s = 960.0;
  /// Latency from the packet's last byte on air to its first byte at the rover's UART (modem
  /// buffering and forward error correction): 50 ms (ours).
  Duration latency = std::chrono::milliseconds(50);
  double loss_probability = 0.0;  ///< each packet lost with this probability
  std::vector<RadioOutage> outages;
};

class RadioLink {
 public:
  RadioLink(const RadioLinkConfig& config, std::uint64_t seed);
  /// When a packet of `bytes` handed over at `t_sent` reaches the rover's UART; nullopt when lost.
  std::optional<Time> Deliver(Time t_sent, std::size_t bytes);
  std::uint64_t sent() const { return sent_; }
  std::uint64_t lost() const { return lost_; }

 private:
  RadioLinkConfig config_;
  std::mt19937_64 rng_;
  Time air_free_{};  // when the air is free for the next packet
  std::uint64_t sent_ = 0, lost_ = 0;
};

}  // namespace hil::rtk

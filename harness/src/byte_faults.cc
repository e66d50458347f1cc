#include "hil/harness/byte_faults.h"

namespace hil::harness {

ByteFaultInjector::ByteFaultInjector(const FaultTimeline& timeline, std::uint64_t seed)
    : timeline_(timeline), rng_(seed * 0x9E3779B97F4A7C15ULL + 0x5EEDULL) {}

bool ByteFaultInjector::Apply(SerialMessage& msg, const std::string& link) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (const auto drop = timeline_.ActiveAt(FaultKind::kFrameDrop, msg.t_ready, link)) {
    if (u(rng_) < drop->Param("probability", 1.0)) {
      ++dropped_;
      return false;
    }
  }
  if (const auto corrupt = timeline_.ActiveAt(FaultKind::kByteCorruption, msg.t_ready, link)) {
    const double p = corrupt->Param("probability", 1e-3);
    std::uniform_int_distribution<int> bit(0, 7);
    for (char& c : msg.bytes) {
      if (u(rng_) < p) {
        c = static_cast<char>(static_cast<unsigned char>(c) ^ (1u << bit(rng_)));
        ++corrupted_;
      }
    }
  }
  return true;
}

}  // namespace hil::harness

#include "hil/firmware_emu/rtk/radio_link.h"

#include <algorithm>

namespace hil::rtk {

RadioLink::RadioLink(const RadioLinkConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed ^ 0x4AD10ULL) {}

std::optional<Time> RadioLink::Deliver(Time t_sent, std::size_t bytes) {
  ++sent_;
  // one draw per packet whatever the outcome, so a change of outages does not shift the losses
  const bool random_loss =
      std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < config_.loss_probability;
  const bool in_outage =
      std::any_of(config_.outages.begin(), config_.outages.end(),
                  [&](const RadioOutage& o) { return t_sent >= o.start && t_sent < o.end; });
  const Time start = std::max(t_sent, air_free_);
  const Time done = start + DurationFromSeconds(static_cast<double>(bytes) / config_.bytes_per_s);
  air_free_ = done;  // a lost packet still used the air
  if (random_loss || in_outage) {
    ++lost_;
    return std::nullopt;
  }
  return done + config_.latency;
}

}  // namespace hil::rtk

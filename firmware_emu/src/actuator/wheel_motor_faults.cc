#include "hil/firmware_emu/actuator/wheel_motor_faults.h"

#include <algorithm>

namespace hil::actuator {
namespace {

// SplitMix64's finaliser: a well-mixed 64-bit hash of `x`.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace

WheelMotorFaults::WheelMotorFaults(std::vector<WheelMotorFault> faults, std::uint64_t seed)
    : faults_(std::move(faults)), counters_(faults_.size()), seed_(seed) {}

Duration WheelMotorFaults::AddedLatency(Time t, std::uint64_t index) {
  Duration added{};
  for (std::size_t i = 0; i < faults_.size(); ++i) {
    const WheelMotorFault& f = faults_[i];
    if (f.kind != WheelMotorFault::Kind::kCommandLatency || !f.ActiveAt(t)) continue;
    // a uniform draw in [0, 1) from the top 53 bits of the hash of (seed, fault, command)
    const std::uint64_t h = Mix(Mix(seed_ ^ Mix(i)) ^ index);
    const double u = static_cast<double>(h >> 11) * 0x1.0p-53;
    const Duration d =
        f.latency + Duration(static_cast<std::int64_t>(u * static_cast<double>(f.jitter.count())));
    WheelMotorFaultCounters& c = counters_[i];
    ++c.events;
    c.added_latency_total += d;
    c.added_latency_max = std::max(c.added_latency_max, d);
    added += d;
  }
  return added;
}

double WheelMotorFaults::SpeedLimit(Time t, double nominal) const {
  double limit = nominal;
  for (const WheelMotorFault& f : faults_) {
    if (f.kind == WheelMotorFault::Kind::kSaturation && f.ActiveAt(t))
      limit = std::min(limit, f.max_wheel_speed_radps);
  }
  return limit;
}

bool WheelMotorFaults::Stuck(Time t) const {
  return std::any_of(faults_.begin(), faults_.end(), [t](const WheelMotorFault& f) {
    return f.kind == WheelMotorFault::Kind::kStuck && f.ActiveAt(t);
  });
}

Time WheelMotorFaults::NextBoundaryAfter(Time t) const {
  Time next = Time::max();
  for (const WheelMotorFault& f : faults_) {
    if (f.start > t) next = std::min(next, f.start);
    if (f.end > t) next = std::min(next, f.end);
  }
  return next;
}

void WheelMotorFaults::NoteCommand(Time t, bool beyond_limit) {
  for (std::size_t i = 0; i < faults_.size(); ++i) {
    const WheelMotorFault& f = faults_[i];
    if (!f.ActiveAt(t)) continue;
    if ((f.kind == WheelMotorFault::Kind::kSaturation && beyond_limit) ||
        f.kind == WheelMotorFault::Kind::kStuck)
      ++counters_[i].events;
  }
}

void WheelMotorFaults::NoteInterval(Time t, double dt_s, bool clamped) {
  for (std::size_t i = 0; i < faults_.size(); ++i) {
    const WheelMotorFault& f = faults_[i];
    if (!f.ActiveAt(t)) continue;
    if (f.kind == WheelMotorFault::Kind::kSaturation && clamped) counters_[i].clamped_s += dt_s;
    if (f.kind == WheelMotorFault::Kind::kStuck) counters_[i].held_s += dt_s;
  }
}

}  // namespace hil::actuator

#include "hil/estimator/drivers/arrival_clock.h"

#include <algorithm>
#include <cmath>

namespace hil::estimator::drivers {
namespace {

constexpr double kRateGain = 0.2;    // smoothing of the host → GPS rate per reference
constexpr double kOffsetGain = 0.5;  // share of a reference's residual taken into the offset
constexpr double kMinRate = 0.01, kMaxRate = 100.0;
constexpr double kAlpha = 0.2, kBeta = 0.02;  // sample tracker gains (β ≤ α²/(2−α): no overshoot)
constexpr double kMaxResidualPeriods = 0.3;
constexpr double kMaxAbsNs = 4e18;  // ±126 years around the GPS epoch

}  // namespace

void ArrivalClock::AddReference(std::int64_t host_ns, GpsTime gps) {
  const bool ordered = references_ > 0 && host_ns > host_prev_ns_ && gps > gps_prev_;
  ++references_;
  auto restart = [&] {
    host_anchor_ns_ = host_ns;
    gps_anchor_ = gps;
    since_restart_ = 1;
  };
  if (!ordered) {
    if (references_ > 1) ++jumps_;
    restart();
  } else {
    const double measured = static_cast<double>((gps - gps_prev_).count()) /
                            static_cast<double>(host_ns - host_prev_ns_);
    if (!(measured > kMinRate && measured < kMaxRate)) {
      ++jumps_;
      restart();
    } else if (since_restart_ == 1) {
      rate_ = measured;
      host_anchor_ns_ = host_ns;
      gps_anchor_ = gps;
      ++since_restart_;
    } else {
      const double residual_s = static_cast<double>((gps - *ToGps(host_ns)).count()) * 1e-9;
      if (std::abs(residual_s) > kJumpS) {
        ++jumps_;
        restart();
      } else {
        rate_ += kRateGain * (measured - rate_);
        const GpsTime predicted = *ToGps(host_ns);
        gps_anchor_ =
            predicted +
            Nanoseconds{std::llround(kOffsetGain * static_cast<double>((gps - predicted).count()))};
        host_anchor_ns_ = host_ns;
        ++since_restart_;
      }
    }
  }
  host_prev_ns_ = host_ns;
  gps_prev_ = gps;
}

std::optional<GpsTime> ArrivalClock::ToGps(std::int64_t host_ns) const {
  if (since_restart_ < 2) return std::nullopt;  // the rate needs two references
  // the offset in double, the anchor kept in integer ns (a double holds 1e18 ns only to 128 ns)
  const double offset = static_cast<double>(host_ns - host_anchor_ns_) * rate_;
  if (!(std::abs(offset) < kMaxAbsNs) ||
      std::abs(static_cast<double>(ToNs(gps_anchor_))) >= kMaxAbsNs) {
    return std::nullopt;  // no plausible time (centuries away)
  }
  return gps_anchor_ + Nanoseconds{std::llround(offset)};
}

void ArrivalClock::Reset() {
  rate_ = 1.0;
  references_ = 0;
  since_restart_ = 0;
}

GpsTime PeriodicSampleTimer::Add(GpsTime measured) {
  auto restart = [&] {
    have_ = true;
    t_ = measured;
    frac_ns_ = 0;
    return measured;
  };
  if (!have_) return restart();
  const std::int64_t d = (measured - t_).count();
  if (d <= 0 || d > max_gap_ns_) {
    ++restarts_;
    return restart();
  }
  if (period_ns_ <= 0) {
    period_ns_ = static_cast<double>(d);
    return restart();
  }
  const double n = std::max(1.0, std::round(static_cast<double>(d) / period_ns_));
  const double predicted = frac_ns_ + n * period_ns_;  // relative to t_
  const double residual = static_cast<double>(d) - predicted;
  if (std::abs(residual) > kMaxResidualPeriods * period_ns_) {
    ++restarts_;
    return restart();
  }
  const double smoothed = predicted + kAlpha * residual;
  period_ns_ += kBeta * residual / n;
  const double whole = std::floor(smoothed);
  t_ += Nanoseconds{static_cast<std::int64_t>(whole)};
  frac_ns_ = smoothed - whole;
  return t_;
}

void PeriodicSampleTimer::Reset() {
  have_ = false;
  period_ns_ = 0;
}

}  // namespace hil::estimator::drivers

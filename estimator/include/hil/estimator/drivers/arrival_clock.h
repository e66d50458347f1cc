#pragma once
/// @file
/// Time for data that carries no sample time of its own (J1939 IMU frames on CAN): the receive time
/// on a host clock (kernel timestamps of a CAN socket) is mapped onto GPS time through reference
/// events seen on the same clock whose GPS time is known (the HIL_TIME_PULSE frame: arrival minus
/// the MCU's queueing latency = the GPS second of the pulse edge). Only differences of host times
/// between a reference and a sample are used: the host clock's offset from GPS time and its rate
/// (any positive rate, so a scaled-time run maps as well) are estimated, never trusted.
/// `PeriodicSampleTimer` then removes arrival jitter from a periodic stream (an alpha-beta tracker
/// of the sample instants and the period, with skipped samples bridged).

#include <cstdint>
#include <optional>

#include "hil/estimator/time_types.h"

namespace hil::estimator::drivers {

/// Host clock → GPS time from reference events (host time, GPS time).
class ArrivalClock {
 public:
  /// A reference event at `host_ns` (host clock) that happened at GPS time `gps`.
  void AddReference(std::int64_t host_ns, GpsTime gps);
  /// GPS time of a host instant; nullopt until two references since the last restart gave the rate.
  std::optional<GpsTime> ToGps(std::int64_t host_ns) const;
  /// Estimated GPS seconds per host second (1 in real time, the scale factor of a scaled run).
  double rate() const { return rate_; }
  std::uint64_t references() const { return references_; }
  /// References that disagreed with the prediction by more than `kJumpS` and restarted the map.
  std::uint64_t jumps() const { return jumps_; }
  void Reset();

  static constexpr double kJumpS = 0.25;

 private:
  double rate_ = 1.0;
  std::int64_t host_anchor_ns_ = 0, host_prev_ns_ = 0;
  GpsTime gps_anchor_{}, gps_prev_{};
  std::uint64_t references_ = 0, jumps_ = 0, since_restart_ = 0;
};

/// Smooths the instants of a periodic sample stream (alpha-beta tracker on GPS time).
class PeriodicSampleTimer {
 public:
  /// `max_gap_s`: a measured instant further than this from the previous one restarts the tracker.
  explicit PeriodicSampleTimer(double max_gap_s = 0.5)
      : max_gap_ns_(static_cast<std::int64_t>(max_gap_s * 1e9)) {}
  /// The smoothed instant of a sample measured at `measured`.
  GpsTime Add(GpsTime measured);
  /// Current period estimate in ns (0 until two samples are seen).
  double period_ns() const { return period_ns_; }
  std::uint64_t restarts() const { return restarts_; }
  void Reset();

 private:
  std::int64_t max_gap_ns_;
  bool have_ = false;
  GpsTime t_{};
  double frac_ns_ = 0;  // sub-ns part of the smoothed instant
  double period_ns_ = 0;
  std::uint64_t restarts_ = 0;
};

}  // namespace hil::estimator::drivers

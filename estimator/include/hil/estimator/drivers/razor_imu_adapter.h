#pragma once
/// @file
/// Turns decoded Razor v13 text lines into IMU samples on GPS time. The stock lines carry no time
/// (razor_text_formats.md), so each line is stamped with its host arrival time, mapped onto GPS
/// time through the arrivals of the GNSS fixes (each taken to arrive a configured latency after
/// its time of validity; an `ArrivalClock`), and smoothed over the periodic stream. Samples before
/// the map exists, or across a gap longer than `max_gap_s`, are counted and dropped. This is the
/// best a host can do with the stock firmware; the binary protocol or CAN (time pulse) are exact.

#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/drivers/arrival_clock.h"
#include "hil/estimator/drivers/arrival_imu_increments.h"
#include "hil/estimator/drivers/razor_text_decoder.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

struct RazorAdapterStats : ArrivalImuCounts {
  std::uint64_t gnss_references = 0;
};

class RazorImuAdapter {
 public:
  explicit RazorImuAdapter(RazorScales scales = {}, double max_gap_s = 0.5)
      : scales_(scales), imu_(max_gap_s) {}
  /// A GNSS fix with time of validity `tov` whose last byte arrived at `host_ns`, `latency_s` after
  /// `tov`.
  void AddGnssArrival(std::int64_t host_ns, GpsTime tov, double latency_s);
  /// One line received at `host_ns`; an IMU sample when it completes an interval.
  std::optional<ImuSample> Add(const RazorTextSample& line, std::int64_t host_ns);
  const RazorAdapterStats& stats() const { return stats_; }
  const ArrivalClock& clock() const { return clock_; }

 private:
  RazorScales scales_;
  ArrivalClock clock_;
  ArrivalImuIncrements imu_;
  RazorAdapterStats stats_;
};

}  // namespace hil::estimator::drivers

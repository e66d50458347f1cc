#pragma once
/// @file
/// What each fault of the timeline actually did in a run: how many injections (messages dropped,
/// duplicated, truncated or garbled by a baud mismatch, bits flipped, CAN frames swapped, MCU
/// resets, receiver messages lost to its transmit buffer, GNSS epochs without a fix or with a
/// glitch) and when. Filled by whoever applies the fault; written to report.json
/// `fault_injections`.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/sim_time.h"
#include "hil/harness/scenario/fault_timeline.h"

namespace hil::harness {

/// The record of one fault of the timeline.
struct FaultInjection {
  std::string kind;  ///< FaultKindName
  std::string link;  ///< "" = every link
  double start_s = 0, end_s = 0;
  std::string unit;  ///< what `count` counts ("messages", "bits", "frames", "resets", …)
  std::uint64_t count = 0;
  std::vector<double> times_s;  ///< emulated times of the first kMaxTimes injections
  std::optional<double>
      recovery_time_s;  ///< evaluator: end of the fault → error back below threshold
  static constexpr std::size_t kMaxTimes = 200;
};

class FaultRecorder {
 public:
  /// One record per fault of `timeline`, in file order.
  explicit FaultRecorder(const FaultTimeline& timeline);
  /// `n` injections of fault `index` at emulated time `t`.
  void Note(std::size_t index, Time t, std::uint64_t n = 1);
  /// The index of the first fault of `kind` active at `t` on `link` (or on every link).
  std::optional<std::size_t> Active(FaultKind kind, Time t, const std::string& link = "") const;
  const std::vector<FaultInjection>& records() const { return records_; }
  std::vector<FaultInjection>& records() { return records_; }

 private:
  const FaultTimeline& timeline_;
  std::vector<FaultInjection> records_;
};

/// The unit a kind's injections are counted in.
const char* FaultUnit(FaultKind kind);

}  // namespace hil::harness

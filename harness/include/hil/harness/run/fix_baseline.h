#pragma once
/// @file
/// The raw-GNSS baseline of a run: the fixes of the first receiver (its antenna is the scenario's
/// antenna lever arm; further receivers of a multi-antenna scenario feed the estimator, not the
/// baseline), taken after each event time's device events, written to gnss_fixes.csv as they come
/// and handed to the evaluation (TakeFixes). The GNSS faults of the timeline are counted here
/// against the fixes they touched (an outage's invalid epochs, a data gap's unsent ones, a glitch's
/// valid ones).

#include <ostream>
#include <vector>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/faults/fault_record.h"
#include "hil/harness/run/device_set.h"

namespace hil::harness {

class FixBaseline {
 public:
  /// `recorder` may be null (nothing counted); `csv` receives one line per valid fix.
  FixBaseline(const DeviceSet& set, FaultRecorder* recorder, std::ostream& csv);
  /// After the device events of time `t`: takes the first receiver's fix if it is of time `t`.
  void Record(Time t);
  /// The valid fixes since the last call, in time order, moved into `out` (cleared first).
  void TakeFixes(std::vector<EstimateRecord>& out) {
    out.clear();
    out.swap(fixes_);
  }

 private:
  const DeviceSet& set_;
  FaultRecorder* recorder_;
  std::ostream& csv_;
  std::vector<EstimateRecord> fixes_;
};

}  // namespace hil::harness

#pragma once
/// @file
/// The truth at a set of times, from one pass of the truth integrator. The evaluation needs the
/// truth at every estimate, at every raw fix and on the 10 Hz grid of truth.csv; integrating a
/// long scenario once instead of once per use saves most of the evaluation's time. A sample from
/// the table is the one a fresh TruthIntegrator gives at that time, bit for bit: the integrator's
/// steps do not depend on which times are sampled (truth_integrator.h).

#include <vector>

#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/truth_sample.h"
#include "hil/truth/local_frame.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

class TruthTable {
 public:
  /// Samples the truth at `times` (any order, repeats allowed; negative times are left out).
  TruthTable(const truth::TruthConfig& config, std::vector<Time> times);
  /// The sample at `t`, one of the times given. @throws std::out_of_range otherwise.
  const TruthSample& At(Time t) const;
  bool Has(Time t) const;
  /// The scenario's local frame (ENU at the origin).
  const truth::LocalFrame& frame() const { return frame_; }

 private:
  std::vector<Time> times_;  // sorted, unique
  std::vector<TruthSample> samples_;
  truth::LocalFrame frame_;
};

}  // namespace hil::harness

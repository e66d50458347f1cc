#include "hil/harness/run/fix_baseline.h"

#include "hil/harness/report/run_outputs.h"

namespace hil::harness {

FixBaseline::FixBaseline(const DeviceSet& set, FaultRecorder* recorder, std::ostream& csv)
    : set_(set), recorder_(recorder), csv_(csv) {}

void FixBaseline::Record(Time t) {
  if (set_.fix_sources.empty()) return;
  const gnss::GnssFix& fix = *set_.fix_sources.front()();
  if (fix.t_validity != t) return;
  if (recorder_) {
    const auto outage = recorder_->Active(FaultKind::kGnssOutage, t);
    if (outage && !fix.valid()) recorder_->Note(*outage, t);
    const auto gap = recorder_->Active(FaultKind::kGnssDataGap, t);
    if (gap) recorder_->Note(*gap, t);  // the receiver computed this epoch but sent nothing
    const auto glitch = recorder_->Active(FaultKind::kGnssGlitch, t);
    if (glitch && fix.valid()) recorder_->Note(*glitch, t);
  }
  if (!fix.valid()) return;
  EstimateRecord r;
  r.t_validity = fix.t_validity;
  r.lat_deg = fix.lat_deg;
  r.lon_deg = fix.lon_deg;
  r.height_m = fix.height_m;
  r.vel_enu_mps = Eigen::Vector3d(fix.vel_e_mps, fix.vel_n_mps, -fix.vel_d_mps);
  fixes_.push_back(r);
  WriteFixCsvLine(csv_, fix);
}

}  // namespace hil::harness

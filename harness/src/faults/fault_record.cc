#include "hil/harness/faults/fault_record.h"

namespace hil::harness {

const char* FaultUnit(FaultKind kind) {
  switch (kind) {
    case FaultKind::kGnssOutage:
      return "epochs without a fix";
    case FaultKind::kGnssDataGap:
      return "epochs not sent";
    case FaultKind::kGnssGlitch:
      return "epochs with the offset";
    case FaultKind::kByteCorruption:
      return "bits flipped";
    case FaultKind::kFrameDrop:
      return "messages dropped";
    case FaultKind::kMcuReset:
      return "resets";
    case FaultKind::kBaudMismatch:
      return "messages garbled";
    case FaultKind::kFrameDuplicate:
      return "messages duplicated";
    case FaultKind::kFrameTruncate:
      return "messages truncated";
    case FaultKind::kCanReorder:
      return "frame pairs swapped";
    case FaultKind::kGnssOverload:
      return "messages lost to the transmit buffer";
    case FaultKind::kControllerStop:
      return "controller processes killed";
    case FaultKind::kCommandLinkLoss:
      return "command bytes (serial) or frames (CAN) lost";
    case FaultKind::kCommandLatency:
      return "commands delayed";
    case FaultKind::kActuatorSaturation:
      return "commands beyond the limit";
    case FaultKind::kActuatorStuck:
      return "commands not followed (output held)";
  }
  return "?";
}

FaultRecorder::FaultRecorder(const FaultTimeline& timeline) : timeline_(timeline) {
  for (const Fault& f : timeline.faults) {
    FaultInjection r;
    r.kind = FaultKindName(f.kind);
    r.link = f.link;
    r.start_s = ToSeconds(f.start);
    r.end_s = ToSeconds(f.end);
    r.unit = FaultUnit(f.kind);
    records_.push_back(std::move(r));
  }
}

void FaultRecorder::Note(std::size_t index, Time t, std::uint64_t n) {
  if (index >= records_.size() || n == 0) return;
  FaultInjection& r = records_[index];
  r.count += n;
  if (r.times_s.size() < FaultInjection::kMaxTimes) r.times_s.push_back(ToSeconds(t));
}

std::optional<std::size_t> FaultRecorder::Active(FaultKind kind, Time t,
                                                 const std::string& link) const {
  for (std::size_t i = 0; i < timeline_.faults.size(); ++i) {
    const Fault& f = timeline_.faults[i];
    if (f.kind == kind && f.ActiveAt(t) && (f.link.empty() || f.link == link)) return i;
  }
  return std::nullopt;
}

}  // namespace hil::harness

#include "hil/harness/engine/pacer.h"

#include <algorithm>

namespace hil::harness {

const char* SteppingName(Stepping stepping) {
  switch (stepping) {
    case Stepping::kVirtual:
      return "virtual";
    case Stepping::kFreeRunning:
      return "free_running";
    case Stepping::kLockstep:
      return "lockstep";
  }
  return "virtual";
}

bool PaceLateness::Note(std::int64_t due_ns, std::int64_t now_ns) {
  ++actions;
  if (due_ns > now_ns) return true;
  if (now_ns - due_ns > kLateNs) ++late;
  max_late_ns = std::max(max_late_ns, now_ns - due_ns);
  return false;
}

}  // namespace hil::harness

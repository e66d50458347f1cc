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

bool PaceLateness::Note(WallTime due, WallTime now) {
  ++actions;
  if (due > now) return true;
  if (now - due > kLate) ++late;
  max_late = std::max(max_late, now - due);
  return false;
}

}  // namespace hil::harness

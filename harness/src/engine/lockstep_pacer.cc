#include "hil/harness/engine/lockstep_pacer.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "hil/harness/engine/device_io.h"

namespace hil::harness {

void LockstepPacer::Start(EngineDevices& devices) {
  for (const auto& ports : devices.endpoints) {
    for (const auto& ep : ports) ep->set_wall_stamps(true);
  }
}

bool LockstepPacer::Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) {
  (void)io, (void)out;
  const std::int64_t due = clock_.WallNsOf(step.t_action);
  if (lateness_.Note(due, link::RealtimePacer::MonotonicNs()))
    std::this_thread::sleep_until(
        std::chrono::steady_clock::time_point(std::chrono::nanoseconds(due)));
  return false;
}

void LockstepPacer::EndOfStep(DeviceIo& io) {
  io.SendAll();  // what the event made leaves now, at its time (virtual mode may hold it back)
}

}  // namespace hil::harness

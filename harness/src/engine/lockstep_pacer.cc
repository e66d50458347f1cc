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
  const WallTime due = clock_.WallTimeOf(step.t_action);
  if (lateness_.Note(due, WallNow())) std::this_thread::sleep_until(ToSteady(due));
  return false;
}

void LockstepPacer::EndOfStep(DeviceIo& io) {
  io.SendAll();  // what the event made leaves now, at its time (virtual mode may hold it back)
}

}  // namespace hil::harness

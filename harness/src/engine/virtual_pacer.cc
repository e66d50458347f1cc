#include "hil/harness/engine/virtual_pacer.h"

#include "hil/harness/engine/device_io.h"

namespace hil::harness {

bool VirtualPacer::Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) {
  (void)step, (void)io, (void)out;
  return false;  // emulated time does not wait for the wall clock
}

bool VirtualPacer::Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) {
  (void)lock;  // no other thread writes
  // a paced host reads its links in runs of messages (VirtualWriteQueue); CAN frames are not
  // paced, so beside a bus every serial chunk goes as soon as it may, as the frames do
  const bool ok = !write || writes_.Pump(false, hold_tail_ && can == nullptr);
  if (can) can->SendAll();
  return ok;
}

bool VirtualPacer::Flush(DeviceIo& io) { return io.SendAll(); }

}  // namespace hil::harness

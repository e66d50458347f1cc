#include "hil/harness/engine/clocked_pacer.h"

#include <algorithm>

namespace hil::harness {

void ClockedPacer::Start(EngineDevices& devices) {
  endpoints_.clear();
  for (const auto& ports : devices.endpoints) {
    for (const auto& ep : ports) endpoints_.push_back(ep.get());
  }
}

bool ClockedPacer::Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) {
  (void)write, (void)lock;
  if (can) can->SendAll();
  return true;
}

bool ClockedPacer::Flush(DeviceIo& io) {
  (void)io;
  for (SerialEndpoint* ep : endpoints_) ep->WriteChunksOrDrop(ep->ChunksEndedBy(Time::max()));
  return true;
}

std::optional<Time> ClockedPacer::NextChunkEnd() const {
  std::optional<Time> t;
  for (const SerialEndpoint* ep : endpoints_) {
    const std::optional<Time> end = ep->next_chunk_end();
    if (end && (!t || *end < *t)) t = end;
  }
  return t;
}

bool ClockedPacer::WriteDue(Time t) {
  bool any = false;
  for (SerialEndpoint* ep : endpoints_) {
    const std::size_t n = ep->ChunksEndedBy(t);
    if (n == 0) continue;
    ep->WriteChunksOrDrop(n);
    any = true;
  }
  return any;
}

}  // namespace hil::harness

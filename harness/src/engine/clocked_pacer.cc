#include "hil/harness/engine/clocked_pacer.h"

#include <sched.h>

#include <algorithm>

#include <sys/stat.h>

#include "hil/harness/lockstep/lockstep_shared.h"

namespace hil::harness {

void ClockedPacer::Start(EngineDevices& devices) {
  endpoints_.clear();
  for (const auto& ports : devices.endpoints) {
    for (const auto& ep : ports) endpoints_.push_back(ep.get());
  }
  // nothing written yet: what the host side holds is all there is
  settled_.assign(endpoints_.size(), 0);
}

bool ClockedPacer::Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) {
  (void)write, (void)lock;
  if (!can) return true;
  if (can->next_frame_time()) bus_written_ = true;
  can->SendAll();
  return true;
}

bool ClockedPacer::Flush(DeviceIo& io) {
  (void)io;  // the drain's turns write what is left, each chunk at its end (ClockedHostTurns)
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

namespace {

// Waits until the host side of `ep` shows `want` unread bytes (a pty hands what its master side
// wrote to the slave's line discipline in a kernel worker: a read on the host side that finds
// bytes there returns them without waiting for the rest, so a chunk not yet handed over would be
// read a read later in some runs). At most ClockedPacer::kHandOverLimit; false when that passed.
bool AwaitHandOver(const SerialEndpoint& ep, std::size_t want) {
  if (ep.PendingToHost() >= want) return true;  // the usual case: no clock read
  const WallTime start = WallNow();
  while (ep.PendingToHost() < want) {
    if (WallNow() - start > ClockedPacer::kHandOverLimit) return false;
    sched_yield();
  }
  return true;
}

}  // namespace

std::uint64_t ClockedPacer::LinkBit(std::size_t k) {
  return k < static_cast<std::size_t>(lockstep::kMaxLinks) ? std::uint64_t{1} << k
                                                           : lockstep::kOtherFd;
}

std::vector<std::uint64_t> ClockedPacer::LinkDevices(
    const std::vector<std::vector<std::unique_ptr<SerialEndpoint>>>& endpoints) {
  std::vector<std::uint64_t> rdevs;
  for (const auto& ports : endpoints) {  // Start's order
    for (const auto& ep : ports) {
      struct stat st {};
      const bool tty = stat(ep->link_path().c_str(), &st) == 0 && S_ISCHR(st.st_mode);
      rdevs.push_back(tty ? static_cast<std::uint64_t>(st.st_rdev) : 0);
    }
  }
  return rdevs;
}

std::size_t ClockedPacer::HeldBefore(std::size_t k) const {
  const SerialEndpoint& ep = *endpoints_[k];
  // the programs are idle and only ever take bytes: with none on its way, the count is exact
  return settled_[k] == ep.bytes_sent() ? ep.HeldForHost() : ep.PendingToHost();
}

std::uint64_t ClockedPacer::WriteDue(Time t) {
  std::uint64_t written = 0;
  for (std::size_t k = 0; k < endpoints_.size(); ++k) {
    SerialEndpoint* ep = endpoints_[k];
    const std::size_t n = ep->ChunksEndedBy(t);
    if (n == 0) continue;
    const std::size_t unread = HeldBefore(k);
    const std::uint64_t dropped = ep->bytes_dropped_unread();
    const std::size_t sent = ep->WriteChunksOrDrop(n);
    const bool whole = unread + sent <= kHandOverBytes && ep->bytes_dropped_unread() == dropped;
    const bool handed_over =
        sent == 0 || AwaitHandOver(*ep, std::min(unread + sent, kHandOverBytes));
    // every byte written is on the host side now (what the programs read since, they took)
    settled_[k] = whole && handed_over ? ep->bytes_sent() : kUnsettled;
    written |= LinkBit(k);
  }
  return written;
}

}  // namespace hil::harness

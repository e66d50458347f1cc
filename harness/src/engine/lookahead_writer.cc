// LookaheadWriter: the links' bytes written ahead of the programs' clock, published with their
// arrival times (lookahead_writer.h).
#include "hil/harness/engine/lookahead_writer.h"

#include <algorithm>
#include <utility>

namespace hil::harness {

LookaheadWriter::LookaheadWriter(lockstep::LockstepHost& host, std::vector<SerialEndpoint*> links,
                                 lockstep::LockstepHost::WaitStep on_wait)
    : host_(host), links_(std::move(links)), on_wait_(std::move(on_wait)) {
  written_.assign(links_.size(), 0);
  queued_.assign(links_.size(), 0);
  counted_.assign(links_.size(), 0);
}

std::size_t LookaheadWriter::MostQueued() {
  std::size_t most = 0;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    // chunks join a link's queue at its back, and leave it from the front only here (no reply
    // goes ahead of them: the programs do not write), so the new ones are counted once
    const SerialEndpoint& ep = *links_[k];
    for (; counted_[k] < ep.queued_chunks(); ++counted_[k])
      queued_[k] += ep.chunk_bytes(counted_[k]);
    most = std::max(most, queued_[k]);
  }
  return most;
}

std::optional<Time> LookaheadWriter::PublishLink(std::size_t k, bool force) {
  SerialEndpoint& ep = *links_[k];
  const int feed = static_cast<int>(k);
  const std::uint64_t unread = written_[k] - host_.FeedConsumed(feed);
  const std::size_t free_entries = host_.FeedFree(feed);
  batch_.clear();
  std::uint64_t end = written_[k];
  std::size_t n = 0;
  std::optional<Time> left;
  for (; n < ep.queued_chunks(); ++n) {
    const std::size_t bytes = ep.chunk_bytes(n);
    const bool room = force || (end - written_[k]) + unread + bytes <= kAheadBytes;
    if (!room || batch_.size() >= free_entries) {
      left = ep.chunk_end(n);
      break;
    }
    end += bytes;
    batch_.emplace_back(end, ep.chunk_end(n));
  }
  if (n == 0) return left;
  // the bytes first, then their arrival: a program that sees one can read them
  MostQueued();  // every chunk counted, before n of them leave
  queued_[k] -= static_cast<std::size_t>(end - written_[k]);
  counted_[k] -= n;
  written_[k] += ep.WriteChunksOrDrop(n);
  ++writes_;
  // a write cut short dropped the rest (captured as such): those chunks bring nothing
  for (const auto& [end_byte, arrival] : batch_)
    host_.Publish(feed, std::min(end_byte, written_[k]), arrival);
  return left;
}

void LookaheadWriter::Publish(Time horizon, bool force) {
  Time h = horizon;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (const std::optional<Time> left = PublishLink(k, force))
      h = std::min(h, *left - Duration(1));
  }
  host_.SetHorizon(h);
}

bool LookaheadWriter::WriteWhatFits(Time horizon) {
  const std::uint64_t before = writes_;
  Publish(horizon, false);
  // nothing fits although the programs have caught up: a link they leave unread (its bytes
  // drop at the pty, as a UART's that nobody reads)
  if (writes_ == before) Publish(horizon, true);
  host_.MoveClock();
  return writes_ != before;
}

bool LookaheadWriter::Step(Time t) {
  const Time horizon = t - Duration(1);  // the events at t make chunks that end after it
  const bool stalled = host_.Stalled();
  if (!stalled && MostQueued() < kBatchBytes) return true;
  Publish(horizon, false);
  if (stalled) host_.MoveClock();
  while (MostQueued() >= kHoldBytes) {
    // hil is far ahead: the programs catch up with the horizon, then read what fits
    if (!host_.WaitStalled(on_wait_)) return false;
    if (!WriteWhatFits(horizon)) break;  // every feed full of chunks beyond the horizon
  }
  return true;
}

bool LookaheadWriter::Finish(Time t) {
  Publish(t, false);
  host_.MoveClock();
  while (MostQueued() > 0) {
    if (!host_.WaitStalled(on_wait_)) return false;
    if (!WriteWhatFits(t)) break;
  }
  host_.SetHorizon(t);
  host_.MoveClock();
  return host_.WaitStalled(on_wait_);
}

}  // namespace hil::harness

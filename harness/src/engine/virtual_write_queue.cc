#include "hil/harness/engine/virtual_write_queue.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace hil::harness {

void VirtualWriteQueue::Add(SerialEndpoint& ep, std::size_t bytes, Time t) {
  if (!fifo_.empty() && fifo_.back().ep == &ep) {
    ++fifo_.back().chunks;
    fifo_.back().bytes += bytes;
    fifo_.back().t_last = std::max(fifo_.back().t_last, t);
  } else {
    fifo_.push_back({&ep, 1, bytes, t, t});
  }
  deferred_ += bytes;
}

bool VirtualWriteQueue::Pump(bool all, bool hold_tail) {
  // Held back: the last batch, which may still grow; with a max_skew (the host orders its inputs
  // itself) every batch until kSkewBatchBytes wait, and then all go: fewer, larger hand-overs.
  const bool skew = gate_ && gate_->max_skew() > Duration{0};
  const std::size_t batch_bytes = skew ? kSkewBatchBytes : kBatchBytes;
  const std::size_t max_deferred = skew ? std::max(max_deferred_, 4 * batch_bytes) : max_deferred_;
  const bool flush =
      !hold_tail || all || deferred_ > max_deferred || (skew && deferred_ >= batch_bytes);
  if (skew && flush) {
    while (!fifo_.empty()) {
      const std::optional<bool> wrote = PumpFrontPerLink(all || deferred_ > max_deferred);
      if (!wrote) return false;
      if (!*wrote) break;  // the host has not read far enough: the rest waits for the next Pump
    }
    return true;
  }
  while (!fifo_.empty()) {
    const Batch b = fifo_.front();
    const bool forced = all || deferred_ > max_deferred;
    if (!flush && (skew || fifo_.size() == 1) && b.bytes < batch_bytes) break;
    if (gate_) {
      if (forced) {
        if (!gate_->BeforeWrite(*b.ep, b.bytes, b.t_first, b.t_last)) return false;
      } else if (!gate_->TryWrite(*b.ep, b.bytes, b.t_first, b.t_last)) {
        break;
      }
    }
    if (!Write(b)) return false;
    deferred_ -= b.bytes;
    fifo_.pop_front();
  }
  return true;
}

bool VirtualWriteQueue::Write(const Batch& b) {
  // a link the host reads never drops a byte: a batch larger than what its pty still takes (it
  // holds 12-20 kB, less than the skew bound and a merged per-link run) waits for the host to
  // read, instead of being cut after PtyPort's 1 s stall while the capture said every byte left
  // (issue 40.6)
  if (!gate_ || !gate_->Reads(*b.ep)) return b.ep->WriteChunks(b.chunks);
  return b.ep->WriteChunks(b.chunks, [this](const std::function<std::size_t()>& write_more) {
    return gate_->WaitForRoom(write_more);
  });
}

std::optional<bool> VirtualWriteQueue::PumpFrontPerLink(bool forced) {
  // The batches at the front that lie within max_skew: their links may be written in any order,
  // each link's runs in one write (the gate still waits for what the host must have read before).
  // Unforced, a link the gate does not let through yet stays queued (at the front: its bytes still
  // come before its later ones) and the others go: the run does not wait for the host.
  const Time t0 = fifo_.front().t_first;
  std::size_t n = 1;
  while (n < fifo_.size() && fifo_[n].t_last - t0 <= gate_->max_skew()) ++n;
  std::vector<Batch> per_link;
  for (std::size_t i = 0; i < n; ++i) {
    const Batch& b = fifo_[i];
    auto it = std::find_if(per_link.begin(), per_link.end(),
                           [&](const Batch& p) { return p.ep == b.ep; });
    if (it == per_link.end()) {
      per_link.push_back(b);
    } else {
      it->chunks += b.chunks;
      it->bytes += b.bytes;
      it->t_last = std::max(it->t_last, b.t_last);
    }
  }
  std::vector<Batch> left;
  for (const Batch& b : per_link) {
    if (forced) {
      if (!gate_->BeforeWrite(*b.ep, b.bytes, b.t_first, b.t_last)) return std::nullopt;
    } else if (!gate_->TryWrite(*b.ep, b.bytes, b.t_first, b.t_last)) {
      left.push_back(b);
      continue;
    }
    if (!Write(b)) return std::nullopt;
    deferred_ -= b.bytes;
  }
  const bool wrote = left.size() < per_link.size();
  fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
  fifo_.insert(fifo_.begin(), left.begin(), left.end());
  return wrote;
}

}  // namespace hil::harness

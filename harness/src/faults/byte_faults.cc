#include "hil/harness/faults/byte_faults.h"

#include <utility>

#include "hil/harness/faults/uart_baud_mismatch.h"

namespace hil::harness {
namespace {

std::optional<std::size_t> ActiveIndex(const FaultTimeline& tl, FaultKind kind, Time t,
                                       const std::string& link) {
  for (std::size_t i = 0; i < tl.faults.size(); ++i) {
    const Fault& f = tl.faults[i];
    if (f.kind == kind && f.ActiveAt(t) && (f.link.empty() || f.link == link)) return i;
  }
  return std::nullopt;
}

}  // namespace

ByteFaultInjector::ByteFaultInjector(const FaultTimeline& timeline, std::uint64_t seed,
                                     FaultRecorder* recorder)
    : timeline_(timeline), recorder_(recorder), rng_(seed * 0x9E3779B97F4A7C15ULL + 0x5EEDULL) {}

void ByteFaultInjector::Note(std::optional<std::size_t> index, Time t, std::uint64_t n) {
  if (recorder_ && index) recorder_->Note(*index, t, n);
}

bool ByteFaultInjector::DropTruncateCorrupt(SerialMessage& msg, const std::string& link) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (const auto i = ActiveIndex(timeline_, FaultKind::kFrameDrop, msg.t_ready, link)) {
    if (u(rng_) < timeline_.faults[*i].Param("probability", 1.0)) {
      ++dropped_;
      Note(i, msg.t_ready);
      return false;
    }
  }
  if (const auto i = ActiveIndex(timeline_, FaultKind::kFrameTruncate, msg.t_ready, link)) {
    if (u(rng_) < timeline_.faults[*i].Param("probability", 1.0) && msg.bytes.size() > 1) {
      std::uniform_int_distribution<std::size_t> keep(1, msg.bytes.size() - 1);
      msg.bytes.resize(keep(rng_));
      Note(i, msg.t_ready);
    }
  }
  if (const auto i = ActiveIndex(timeline_, FaultKind::kByteCorruption, msg.t_ready, link)) {
    const Fault& f = timeline_.faults[*i];
    const double ber = f.Param("bit_error_rate", 0.0);
    std::uint64_t flipped = 0;
    if (ber > 0) {
      // independent bit errors: the distance to the next flipped bit is geometric
      std::geometric_distribution<std::uint64_t> skip(ber);
      const std::uint64_t bits = msg.bytes.size() * 8;
      for (std::uint64_t b = skip(rng_); b < bits; b += 1 + skip(rng_)) {
        char& c = msg.bytes[static_cast<std::size_t>(b / 8)];
        c = static_cast<char>(static_cast<unsigned char>(c) ^ (1u << (b % 8)));
        ++flipped;
      }
    } else {
      const double p = f.Param("probability", 1e-3);
      std::uniform_int_distribution<int> bit(0, 7);
      for (char& c : msg.bytes) {
        if (u(rng_) < p) {
          c = static_cast<char>(static_cast<unsigned char>(c) ^ (1u << bit(rng_)));
          ++flipped;
        }
      }
    }
    corrupted_ += flipped;
    Note(i, msg.t_ready, flipped);
  }
  return true;
}

bool ByteFaultInjector::Apply(SerialMessage& msg, const std::string& link) {
  return DropTruncateCorrupt(msg, link);
}

void ByteFaultInjector::Process(const SerialMessage& in, const std::string& link, int link_baud,
                                std::vector<SerialMessage>& out) {
  SerialMessage msg = in;
  if (!DropTruncateCorrupt(msg, link)) return;
  if (link_baud > 0) {
    if (const auto i = ActiveIndex(timeline_, FaultKind::kBaudMismatch, msg.t_ready, link)) {
      const int tx_baud = static_cast<int>(timeline_.faults[*i].Param("baud", 4800));
      if (tx_baud != link_baud) {
        msg.bytes = ReceiveAtWrongBaud(msg.bytes, tx_baud, link_baud).received;
        Note(i, msg.t_ready);
      }
    }
  }
  if (msg.bytes.empty()) return;
  bool twice = false;
  if (const auto i = ActiveIndex(timeline_, FaultKind::kFrameDuplicate, msg.t_ready, link)) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    twice = u(rng_) < timeline_.faults[*i].Param("probability", 1.0);
    if (twice) Note(i, msg.t_ready);
  }
  out.push_back(msg);
  if (twice) out.push_back(std::move(msg));
}

void ByteFaultInjector::ProcessCan(std::vector<CanFrame>& frames) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    const auto i = ActiveIndex(timeline_, FaultKind::kCanReorder, frames[k].t, "");
    if (!i || !(u(rng_) < timeline_.faults[*i].Param("probability", 1.0))) continue;
    std::swap(frames[k], frames[k + 1]);
    std::swap(frames[k].t, frames[k + 1].t);  // bus times stay in order; the contents swap
    Note(i, frames[k].t);
    ++k;  // a frame moves at most one place
  }
}

}  // namespace hil::harness

#include "hil/harness/serial_endpoint.h"

#include <stdexcept>

namespace hil::harness {
namespace {

std::string Hex(std::string_view bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string o;
  o.reserve(bytes.size() * 2);
  for (unsigned char c : bytes) {
    o += kHex[c >> 4];
    o += kHex[c & 15];
  }
  return o;
}

}  // namespace

SerialEndpoint::SerialEndpoint(std::string link_name, const std::string& link_path, int baud,
                               std::size_t tx_buffer_bytes, const std::string& capture_path)
    : link_name_(std::move(link_name)), pty_(link_path, baud), uart_(baud, tx_buffer_bytes), capture_(capture_path) {
  if (!capture_) throw std::runtime_error("cannot write " + capture_path);
  capture_ << "# hil capture v1: link " << link_name_ << ", baud " << baud << "\n"
           << "# dir t_emu_ns byte_period_ns t_wall_ns name hex_bytes\n";
}

void SerialEndpoint::Queue(const SerialMessage& msg) {
  auto chunk = uart_.Submit(msg.t_ready, msg.bytes);
  if (!chunk) {
    capture_ << "drop " << ToNs(msg.t_ready) << " 0 0 " << msg.name << " " << Hex(msg.bytes) << "\n";
    return;
  }
  capture_ << "tx " << ToNs(chunk->t_first) << " " << chunk->byte_period.count() << " 0 " << msg.name << " "
           << Hex(chunk->bytes) << "\n";
  pending_.push_back(std::move(*chunk));
}

std::optional<Time> SerialEndpoint::next_byte_time() const {
  if (pending_.empty()) return std::nullopt;
  return pending_.front().t_byte(pending_offset_);
}

void SerialEndpoint::WriteNextByte(const link::RealtimePacer& pacer) {
  if (pending_.empty()) return;
  const link::TimedChunk& c = pending_.front();
  const Time t = c.t_byte(pending_offset_);
  const std::int64_t wall = pacer.SleepUntil(t);
  pty_.Write(std::string_view(c.bytes).substr(pending_offset_, 1));
  schedule_error_us_.push_back(static_cast<double>(wall - pacer.WallNsOf(t)) * 1e-3);
  if (++pending_offset_ == c.bytes.size()) {
    pending_.pop_front();
    pending_offset_ = 0;
  }
}

void SerialEndpoint::WriteAll() {
  for (const link::TimedChunk& c : pending_) {
    pty_.Write(std::string_view(c.bytes).substr(pending_offset_));
    pending_offset_ = 0;
  }
  pending_.clear();
}

std::string SerialEndpoint::PollHost(Time t_now) {
  std::string rx = pty_.ReadAvailable();
  if (!rx.empty()) {
    capture_ << "rx " << ToNs(t_now) << " 0 " << link::RealtimePacer::MonotonicNs() << " host " << Hex(rx) << "\n";
  }
  return rx;
}

}  // namespace hil::harness

#include "hil/harness/links/serial_endpoint.h"

#include <algorithm>
#include <stdexcept>

#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/link/tty_port.h"

namespace hil::harness {
namespace {

std::unique_ptr<link::SerialPort> OpenPort(const std::string& link_name,
                                           const std::string& link_path, int baud) {
  if (link::IsDevicePath(link_name)) return std::make_unique<link::TtyPort>(link_name, baud);
  return std::make_unique<link::PtyPort>(link_path, baud);
}

CaptureHeader SerialHeader(const std::string& link_name, int baud) {
  CaptureHeader h;
  h.link = link_name;
  h.kind = "serial";
  h.baud = baud;
  return h;
}

}  // namespace

std::string CaptureFileName(const std::string& link_name) {
  const std::size_t slash = link_name.rfind('/');
  return (slash == std::string::npos ? link_name : link_name.substr(slash + 1)) + ".cap";
}

SerialEndpoint::SerialEndpoint(std::string link_name, const std::string& link_path, int baud,
                               std::size_t tx_buffer_bytes, const std::string& capture_path)
    : link_name_(std::move(link_name)),
      port_(OpenPort(link_name_, link_path, baud)),
      uart_(baud, tx_buffer_bytes),
      capture_(capture_path, SerialHeader(link_name_, baud)) {}

SerialEndpoint::~SerialEndpoint() {
  FinishRealtimeRecords();
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    const auto& [chunk, name] = pending_[i];
    const std::size_t from = i == 0 ? pending_offset_ : 0;  // the bytes that did not leave
    CaptureRecord r;
    r.dir = CaptureDir::kDrop;  // nobody got them: the reader went away or the run stopped early
    r.t_emu_ns = ToNs(chunk.t_byte(from));
    r.byte_period_ns = chunk.byte_period.count();
    r.name = name;
    r.bytes = chunk.bytes.substr(from);
    capture_.Write(r);
    ++chunks_done_;
    WriteDueOverflows();
  }
  chunks_done_ = chunks_queued_;
  WriteDueOverflows();
}

void SerialEndpoint::RecordOverflow(const SerialMessage& msg) {
  CaptureRecord r;
  r.dir = CaptureDir::kDrop;
  r.t_emu_ns = ToNs(msg.t_ready);
  r.name = msg.name;
  r.bytes = msg.bytes;
  // captured after the chunks queued before it, whenever the host reads those: its place in the
  // capture is then the same in every run
  overflows_.emplace_back(chunks_queued_, std::move(r));
  WriteDueOverflows();
}

void SerialEndpoint::WriteDueOverflows() {
  while (!overflows_.empty() && overflows_.front().first <= chunks_done_) {
    FinishRealtimeRecords();  // a real-time line in progress goes first
    capture_.Write(overflows_.front().second);
    overflows_.pop_front();
  }
}

bool SerialEndpoint::Queue(const SerialMessage& msg) {
  const std::string name = msg.name.empty() ? "-" : msg.name;
  if (msg.byte_period) {  // timed already (a replay): the bytes keep their recorded times
    pending_.emplace_back(link::TimedChunk{msg.t_ready, *msg.byte_period, msg.bytes}, name);
    ++chunks_queued_;
    return true;
  }
  if (msg.reply) {
    // a chunk partly written to the host cannot move: the reply may only go behind it
    const std::size_t first = pending_offset_ > 0 ? 1 : 0;
    std::vector<link::TimedChunk*> waiting;
    for (std::size_t i = first; i < pending_.size(); ++i) waiting.push_back(&pending_[i].first);
    const Time line_free = first == 1 ? pending_.front().first.t_end() : written_end_;
    auto placed = uart_.SubmitAhead(msg.t_ready, msg.bytes, line_free, waiting);
    if (!placed) {
      RecordOverflow(msg);
      return false;
    }
    const auto at = pending_.begin() + static_cast<std::ptrdiff_t>(first + placed->index);
    pending_.emplace(at, std::move(placed->chunk), name);
    ++chunks_queued_;
    last_queued_end_ = std::max(last_queued_end_, pending_.back().first.t_end());
    return true;
  }
  auto chunk = uart_.Submit(msg.t_ready, msg.bytes);
  if (!chunk) {
    RecordOverflow(msg);
    return false;
  }
  last_queued_end_ = std::max(last_queued_end_, chunk->t_end());
  pending_.emplace_back(std::move(*chunk), name);
  ++chunks_queued_;
  return true;
}

void SerialEndpoint::PopFront() {
  written_end_ = std::max(written_end_, pending_.front().first.t_end());
  pending_.pop_front();
  pending_offset_ = 0;
  ++chunks_done_;
  WriteDueOverflows();
}

std::optional<Time> SerialEndpoint::next_byte_time() const {
  if (pending_.empty()) return std::nullopt;
  return pending_.front().first.t_byte(pending_offset_);
}

void SerialEndpoint::FinishRealtimeRecords() {
  if (!current_.bytes.empty()) capture_.Write(current_);
  if (!current_drop_.bytes.empty()) capture_.Write(current_drop_);
  current_ = CaptureRecord{};
  current_drop_ = CaptureRecord{};
}

void SerialEndpoint::RecordRealtimeByte(bool left, Time t, WallTime wall, Duration period,
                                        const std::string& name, char byte) {
  CaptureRecord& r = left ? current_ : current_drop_;
  CaptureRecord& other = left ? current_drop_ : current_;
  if (!other.bytes.empty()) {  // the line changed between sending and dropping: a new record
    capture_.Write(other);
    other = CaptureRecord{};
  }
  if (r.bytes.empty()) {
    r.dir = left ? CaptureDir::kTx : CaptureDir::kDrop;
    r.t_emu_ns = ToNs(t);
    r.byte_period_ns = period.count();
    r.t_wall = left ? wall : WallTime{};  // a dropped byte was never written
    r.name = name;
  }
  r.bytes.push_back(byte);
  if (left) r.wall_offsets_ns.push_back((wall - r.t_wall).count());
}

void SerialEndpoint::WriteNextByte(const link::RealtimePacer& pacer) {
  if (pending_.empty()) return;
  const auto& [c, name] = pending_.front();
  const Time t = c.t_byte(pending_offset_);
  const WallTime scheduled = pacer.WallTimeOf(t);
  pacer.SleepUntil(t);
  // a UART sends whether or not anyone listens: a byte nobody can take now is dropped, never
  // waited for (that would stall every link of the run), and captured as a drop
  const std::string_view byte = std::string_view(c.bytes).substr(pending_offset_, 1);
  const bool attached = port_->HostAttached();
  const bool left = attached && port_->WriteNow(byte) == 1;
  const WallTime wall = WallNow();
  if (left) {
    ++bytes_sent_;
    schedule_error_us_.Add(static_cast<double>((wall - scheduled).count()) * 1e-3);
  } else {
    ++bytes_dropped_unread_;
    if (attached) ++bytes_dropped_attached_;  // its input queue was full
  }
  RecordRealtimeByte(left, t, wall, c.byte_period, name, byte[0]);
  if (++pending_offset_ == c.bytes.size()) {
    FinishRealtimeRecords();
    PopFront();
  }
}

void SerialEndpoint::Consume(std::size_t bytes, CaptureDir dir, WallTime wall) {
  while (bytes > 0 && !pending_.empty()) {
    const auto& [c, name] = pending_.front();
    const std::size_t n = std::min(bytes, c.bytes.size() - pending_offset_);
    CaptureRecord r;
    r.dir = dir;
    r.t_emu_ns = ToNs(c.t_byte(pending_offset_));
    r.byte_period_ns = c.byte_period.count();
    r.t_wall = dir == CaptureDir::kTx ? wall : WallTime{};
    r.name = name;
    r.bytes = c.bytes.substr(pending_offset_, n);
    capture_.Write(r);
    if (dir == CaptureDir::kTx) bytes_sent_ += n;
    bytes -= n;
    pending_offset_ += n;
    if (pending_offset_ == c.bytes.size()) PopFront();
  }
}

bool SerialEndpoint::WriteChunks(std::size_t chunks, const RoomWait& wait_for_room) {
  chunks = std::min(chunks, pending_.size());
  if (chunks == 0) return true;
  // one write for the chunks: the host reads a byte stream, the chunking is not its business
  write_buffer_.clear();
  for (std::size_t i = 0; i < chunks; ++i)
    write_buffer_.append(pending_[i].first.bytes, i == 0 ? pending_offset_ : 0, std::string::npos);
  std::size_t sent = 0, lost = 0;
  bool all = true;
  if (wait_for_room) {
    // a host that reads this link loses nothing: while its input queue is full (a pty holds
    // 12-20 kB) the caller waits for it to read, with the run's watchdog
    bool failed = false;
    const auto write_more = [&]() -> std::size_t {
      if (failed) return 0;
      const long n = port_->WriteNow(std::string_view(write_buffer_).substr(sent));
      if (n < 0) failed = true;
      sent += n > 0 ? static_cast<std::size_t>(n) : 0;
      return failed ? 0 : write_buffer_.size() - sent;
    };
    all = wait_for_room(write_more);
    if (failed) lost = write_buffer_.size() - sent;
    bytes_dropped_attached_ += lost;  // the host reads this link: a failed port lost them
  } else {
    // nobody paces this link: what a pty nobody reads cannot take is dropped (PtyPort::Write).
    // A port nobody has open drops everything at once, as a UART with no listener: filling the
    // pty's buffer first would end at a wall-clock stall timeout, and two runs of one seed would
    // differ in where their captures turn to drops.
    const long n = port_->HostAttached() ? port_->Write(write_buffer_) : 0;
    sent = n > 0 ? static_cast<std::size_t>(n) : 0;
    lost = write_buffer_.size() - sent;
  }
  bytes_dropped_unread_ += lost;
  // virtual mode: no wall time, so a scenario and seed give an identical capture
  Consume(sent, CaptureDir::kTx, wall_stamps_ ? WallNow() : WallTime{});
  Consume(lost, CaptureDir::kDrop, WallTime{});
  return all;
}

std::optional<Time> SerialEndpoint::next_chunk_end() const {
  if (pending_.empty()) return std::nullopt;
  return pending_.front().first.t_end();
}

std::size_t SerialEndpoint::ChunksEndedBy(Time t) const {
  std::size_t n = 0;
  while (n < pending_.size() && pending_[n].first.t_end() <= t) ++n;
  return n;
}

std::size_t SerialEndpoint::WriteChunksOrDrop(std::size_t chunks) {
  chunks = std::min(chunks, pending_.size());
  if (chunks == 0) return 0;
  write_buffer_.clear();
  for (std::size_t i = 0; i < chunks; ++i)
    write_buffer_.append(pending_[i].first.bytes, i == 0 ? pending_offset_ : 0, std::string::npos);
  const long n = port_->WriteNow(write_buffer_);
  const std::size_t sent = n > 0 ? static_cast<std::size_t>(n) : 0;
  const std::size_t lost = write_buffer_.size() - sent;
  bytes_dropped_unread_ += lost;
  bytes_dropped_attached_ += lost;
  Consume(sent, CaptureDir::kTx, WallTime{});
  Consume(lost, CaptureDir::kDrop, WallTime{});
  return sent;
}

std::size_t SerialEndpoint::queued_bytes() const {
  std::size_t n = 0;
  for (const auto& [c, name] : pending_) n += c.bytes.size();
  return n - pending_offset_;
}

std::string SerialEndpoint::PollHost(Time t_now, bool virtual_time) {
  std::string rx = port_->ReadAvailable();
  if (!rx.empty()) {
    CaptureRecord r;
    r.dir = CaptureDir::kRx;
    r.t_emu_ns = ToNs(t_now);
    r.t_wall = virtual_time && !wall_stamps_ ? WallTime{} : WallNow();
    r.name = "host";
    r.bytes = rx;
    capture_.Write(r);
  }
  return rx;
}

}  // namespace hil::harness

#include "hil/harness/links/can_endpoint.h"

#include <time.h>

#include <algorithm>
#include <stdexcept>

namespace hil::harness {
namespace {

// The socket options, after checking that the kernel has CAN at all (for a helpful message).
link::SocketCanPort::Options BusOptions(const std::string& iface, bool fd) {
  if (!link::SocketCanPort::Available()) {
    throw std::runtime_error(
        "cannot use the CAN interface " + iface +
        ": this kernel has no SocketCAN (AF_CAN); run CAN scenarios in the vcan VM "
        "(ci/vcan/run_in_vm) or on a host with can/vcan modules");
  }
  link::SocketCanPort::Options o;
  o.fd = fd;
  o.receive_own_frames = true;  // our frames come back stamped like everyone's (bus order)
  return o;
}

CaptureHeader CanHeader(const std::string& iface, UnixTime start_utc) {
  CaptureHeader h;
  h.link = iface;
  h.kind = "can";
  h.iface = iface;
  if (start_utc != UnixTime{}) h.start_utc = start_utc;  // the epoch: not known (replay)
  return h;
}

// The offset of the two clocks' epochs: a kernel receive stamp (UTC) minus it is the same
// instant on the wall clock.
Duration RealtimeMinusMonotonic() {
  const UnixTime utc = UnixClock::now();
  const WallTime wall = WallNow();
  return utc.time_since_epoch() - wall.time_since_epoch();
}

}  // namespace

CanEndpoint::CanEndpoint(const std::string& iface, const std::string& capture_dir,
                         UnixTime start_utc, bool fd)
    : port_(iface, BusOptions(iface, fd)),
      start_utc_(start_utc),
      candump_(capture_dir + "/" + iface + ".candump"),
      capture_(capture_dir + "/" + iface + ".cap", CanHeader(iface, start_utc)),
      realtime_minus_mono_(RealtimeMinusMonotonic()),
      tx_counter_(iface) {}

CanEndpoint::~CanEndpoint() {
  try {
    FinishCapture(Duration::zero());  // frames others sent after the last PollBus are captured
  } catch (const std::exception&) {   // a capture that cannot be written is noticed by the run
  }
}

void CanEndpoint::Queue(const CanFrame& frame) {
  // keep the queue in time order; equal times keep their arrival order
  const auto at = std::upper_bound(pending_.begin(), pending_.end(), frame.t,
                                   [](Time t, const CanFrame& f) { return t < f.t; });
  pending_.insert(at, frame);
}

std::optional<Time> CanEndpoint::next_frame_time() const {
  if (pending_.empty()) return std::nullopt;
  return pending_.front().t;
}

void CanEndpoint::Capture(CaptureDir dir, Time t, WallTime wall, const link::CanWireFrame& f) {
  CaptureArrivalsUpTo(t);
  t = std::max(t, t_last_capture_);
  t_last_capture_ = t;
  CaptureRecord r;
  r.dir = dir;
  r.t_emu_ns = ToNs(t);
  r.t_wall = wall;
  r.name = port_.ifname();
  r.frame = f;
  capture_.Write(r);
  link::CandumpRecord c;
  c.t = UtcAt(start_utc_, t);
  c.iface = port_.ifname();
  c.frame = f;
  candump_.Write(c);
}

std::pair<Time, WallTime> CanEndpoint::BusTime(const link::ReceivedCanFrame& r,
                                               const link::RealtimePacer& pacer) {
  const WallTime mono = r.t_kernel > UnixTime{}
                            ? WallTime{r.t_kernel.time_since_epoch() - realtime_minus_mono_}
                            : r.t_read_mono;  // no stamp came
  return {pacer.SimTimeOfWall(mono), mono};
}

void CanEndpoint::SendNext(const link::RealtimePacer& pacer) {
  pacer_ = pacer;
  if (pending_.empty()) return;
  const CanFrame f = pending_.front();
  pending_.pop_front();
  const WallTime scheduled = pacer.WallTimeOf(f.t);
  pacer.SleepUntil(f.t);
  const link::CanWireFrame w = link::FromDeviceFrame(f);
  const auto sent = port_.Send(w);
  if (!sent) return;  // it never left: counted in stats(), not captured
  schedule_error_us_.Add(static_cast<double>((*sent - scheduled).count()) * 1e-3);
  awaiting_echo_.push_back({w, f.t, *sent, false});
  ReadBus(f.t, &pacer, Duration::zero());  // capture it (and what came before) in bus order now
}

void CanEndpoint::SendAll() {
  while (!pending_.empty()) {
    const CanFrame f = pending_.front();
    pending_.pop_front();
    const link::CanWireFrame w = link::FromDeviceFrame(f);
    if (!port_.Send(w)) continue;
    // virtual mode: no wall time (deterministic capture)
    Capture(CaptureDir::kFrameTx, f.t, WallTime{}, w);
    awaiting_echo_.push_back({w, f.t, WallTime{}, true});
  }
}

void CanEndpoint::CaptureUnechoed() {
  const Sent s = awaiting_echo_.front();
  awaiting_echo_.pop_front();
  if (s.captured) return;
  const Time t = pacer_ ? pacer_->SimTimeOfWall(s.t_write_mono) : s.t_scheduled;
  Capture(CaptureDir::kFrameTx, t, s.t_write_mono, s.frame);
}

void CanEndpoint::OnEcho(const link::ReceivedCanFrame& r, Time t, WallTime mono) {
  // echoes come in the order the frames were written; one the receive queue dropped is skipped
  const auto match = std::find_if(awaiting_echo_.begin(), awaiting_echo_.end(),
                                  [&](const Sent& s) { return s.frame == r.frame; });
  if (match == awaiting_echo_.end()) {  // not ours to account for (sent before a restart?)
    Capture(CaptureDir::kFrameTx, t, mono, r.frame);
    return;
  }
  while (awaiting_echo_.begin() != match) CaptureUnechoed();
  const bool captured = awaiting_echo_.front().captured;
  awaiting_echo_.pop_front();
  if (!captured) Capture(CaptureDir::kFrameTx, t, mono, r.frame);
}

void CanEndpoint::ReadBus(Time t_now, const link::RealtimePacer* pacer, Duration wait) {
  const WallTime give_up = WallNow() + wait;
  for (;;) {
    std::optional<link::ReceivedCanFrame> r = port_.Receive(Duration::zero());
    if (!r) {
      const Duration left = give_up - WallNow();
      if (awaiting_echo_.empty() || left <= Duration::zero()) return;
      r = port_.Receive(std::min<Duration>(left, std::chrono::milliseconds(10)));
      if (!r) continue;
    }
    Take(*r, t_now, pacer);
  }
}

void CanEndpoint::Take(const link::ReceivedCanFrame& r, Time t_now,
                       const link::RealtimePacer* pacer) {
  if (!r.frame.error) ++frames_read_;
  const auto [t, mono] = pacer ? BusTime(r, *pacer) : std::pair{t_now, r.t_read_mono};
  if (r.own && !r.frame.error) {
    OnEcho(r, t, mono);
    return;
  }
  if (stamp_at_turns_ && !pacer) {
    unstamped_.push_back(r.frame);
    return;
  }
  Capture(CaptureDir::kFrameRx, t, mono, r.frame);
  if (!r.frame.error) inbox_.push_back(link::ToDeviceFrame(r.frame, t));
}

void CanEndpoint::AwaitSentFrames(Time t_now, Duration limit) {
  if (!tx_counter_.available()) return;
  const WallTime give_up = WallNow() + limit;
  for (;;) {
    const std::optional<std::uint64_t> sent = tx_counter_.SentSinceStart();
    if (!sent || frames_read_ >= *sent) return;
    const Duration left = give_up - WallNow();
    if (left <= Duration::zero()) {
      ++sent_frames_wait_timeouts_;
      return;
    }
    const std::optional<link::ReceivedCanFrame> r =
        port_.Receive(std::min<Duration>(left, std::chrono::milliseconds(10)));
    if (r) Take(*r, t_now, nullptr);
  }
}

void CanEndpoint::AwaitEchoes(Time t_now, Duration limit) {
  ReadBus(t_now, nullptr, limit);
  if (awaiting_echo_.empty()) return;
  ++sent_frames_wait_timeouts_;
  while (!awaiting_echo_.empty()) CaptureUnechoed();  // a lost echo is not waited for again
}

std::vector<CanFrame> CanEndpoint::TakeArrivals(Time t_arrival) {
  AwaitSentFrames(t_arrival, kSentFramesWait);
  ReadBus(t_arrival, nullptr, Duration::zero());
  std::vector<CanFrame> out;
  for (const link::CanWireFrame& f : unstamped_) {
    arrivals_.emplace_back(t_arrival, f);  // turns come in time order: the queue stays sorted
    if (!f.error) out.push_back(link::ToDeviceFrame(f, t_arrival));
  }
  unstamped_.clear();
  return out;
}

void CanEndpoint::CaptureArrivalsUpTo(Time t) {
  while (!arrivals_.empty() && arrivals_.front().first <= t) {
    const auto [t_arrival, f] = arrivals_.front();
    arrivals_.pop_front();
    Capture(CaptureDir::kFrameRx, t_arrival, WallTime{}, f);
  }
}

std::vector<CanFrame> CanEndpoint::PollBus(Time t_now, const link::RealtimePacer* pacer) {
  if (pacer) pacer_ = *pacer;
  ReadBus(t_now, pacer, Duration::zero());
  std::vector<CanFrame> out;
  out.swap(inbox_);
  return out;
}

void CanEndpoint::FinishCapture(Duration timeout) {
  if (pacer_) {
    const link::RealtimePacer pacer = *pacer_;
    ReadBus(pacer.SimTimeOfWall(WallNow()), &pacer,
            awaiting_echo_.empty() ? Duration::zero() : timeout);
  }
  while (!awaiting_echo_.empty()) CaptureUnechoed();
  if (stamp_at_turns_) {
    // what the host sent after the run's last turn reached no device: captured after the rest
    const Time t_end = arrivals_.empty() ? t_last_capture_ : arrivals_.back().first;
    TakeArrivals(t_end);
    CaptureArrivalsUpTo(t_end);
  }
}

}  // namespace hil::harness

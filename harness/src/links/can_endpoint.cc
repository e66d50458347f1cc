#include "hil/harness/links/can_endpoint.h"

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
  return o;
}

CaptureHeader CanHeader(const std::string& iface, std::int64_t start_unix_ns) {
  CaptureHeader h;
  h.link = iface;
  h.kind = "can";
  h.iface = iface;
  h.start_unix_ns = start_unix_ns;
  return h;
}

}  // namespace

CanEndpoint::CanEndpoint(const std::string& iface, const std::string& capture_dir,
                         std::int64_t start_unix_ns, bool fd)
    : port_(iface, BusOptions(iface, fd)),
      start_unix_ns_(start_unix_ns),
      candump_(capture_dir + "/" + iface + ".candump"),
      capture_(capture_dir + "/" + iface + ".cap", CanHeader(iface, start_unix_ns)) {}

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

void CanEndpoint::Capture(CaptureDir dir, Time t, std::int64_t wall_ns,
                          const link::CanWireFrame& f) {
  CaptureRecord r;
  r.dir = dir;
  r.t_emu_ns = ToNs(t);
  r.t_wall_ns = wall_ns;
  r.name = port_.ifname();
  r.frame = f;
  capture_.Write(r);
  link::CandumpRecord c;
  c.t_unix_ns = start_unix_ns_ + ToNs(t);
  c.iface = port_.ifname();
  c.frame = f;
  candump_.Write(c);
}

void CanEndpoint::SendNext(const link::RealtimePacer& pacer) {
  if (pending_.empty()) return;
  const CanFrame f = pending_.front();
  pending_.pop_front();
  const std::int64_t scheduled = pacer.WallNsOf(f.t);
  pacer.SleepUntil(f.t);
  const link::CanWireFrame w = link::FromDeviceFrame(f);
  const auto sent = port_.Send(w);
  if (sent) schedule_error_us_.push_back(static_cast<double>(*sent - scheduled) * 1e-3);
  Capture(CaptureDir::kFrameTx, f.t, sent.value_or(0), w);
}

void CanEndpoint::SendAll() {
  while (!pending_.empty()) {
    const CanFrame f = pending_.front();
    pending_.pop_front();
    const link::CanWireFrame w = link::FromDeviceFrame(f);
    port_.Send(w);
    Capture(CaptureDir::kFrameTx, f.t, 0, w);  // virtual mode: no wall time (deterministic capture)
  }
}

std::vector<CanFrame> CanEndpoint::PollBus(Time t_now) {
  std::vector<CanFrame> out;
  while (auto r = port_.Receive(Duration::zero())) {
    Capture(CaptureDir::kFrameRx, t_now, r->t_read_mono_ns, r->frame);
    if (!r->frame.error) out.push_back(link::ToDeviceFrame(r->frame, t_now));
  }
  return out;
}

}  // namespace hil::harness

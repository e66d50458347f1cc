#include "hil/harness/run/scheduler.h"

#include <poll.h>

#include <algorithm>

#include "hil/truth/truth_integrator.h"

namespace hil::harness {
namespace {

/// In real time, how long the scheduler sleeps at most before it looks for host bytes again.
constexpr Duration kHostPollPeriod = std::chrono::milliseconds(1);

}  // namespace

Scheduler::Scheduler(DeviceSet& devices, const link::RealtimePacer* pacer, Time t_end)
    : set_(devices), pacer_(pacer), t_end_(t_end) {}

void Scheduler::Dispatch(std::size_t d, DeviceOutput& out) {
  std::vector<SerialMessage> carried;
  for (SerialMessage& m : out.serial) {
    SerialEndpoint& ep = *set_.endpoints[d].at(static_cast<std::size_t>(m.port));
    carried.clear();
    if (faults_) {
      faults_->Process(m, ep.link_name(), ep.uart().baud(), carried);
    } else {
      carried.push_back(m);
    }
    for (const SerialMessage& c : carried) {
      if (ep.Queue(c)) {
        if (!pacer_) writes_.Add(ep, c.bytes.size());
        continue;
      }
      if (!recorder_) continue;
      // the receiver's transmit buffer overflowed: count it against an active output overload
      if (const auto i = recorder_->Active(FaultKind::kGnssOverload, c.t_ready))
        recorder_->Note(*i, c.t_ready);
    }
  }
  if (set_.can) {
    if (faults_) faults_->ProcessCan(out.can);
    for (const CanFrame& f : out.can) set_.can->Queue(f);
  }
  out.clear();
  if (!pacer_) {
    if (!write_refused_ && !writes_.Pump(false)) write_refused_ = true;
    if (set_.can) set_.can->SendAll();
  }
}

bool Scheduler::PollHosts(Time t_host, DeviceOutput& out) {
  // one poll() for every port instead of a read() each: hosts rarely write
  if (host_fds_.empty()) {
    for (const auto& ports : set_.endpoints) {
      for (const auto& ep : ports) host_fds_.push_back({ep->host_input_fd(), POLLIN, 0});
    }
  }
  for (pollfd& p : host_fds_) p.revents = 0;
  poll(host_fds_.data(), host_fds_.size(), 0);
  bool replied = false;
  std::size_t k = 0;
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    const Time t_rx = pacer_ ? pacer_->SimTimeOfWall(link::RealtimePacer::MonotonicNs()) : t_host;
    for (std::size_t p = 0; p < set_.endpoints[d].size(); ++p) {
      const pollfd& pf = host_fds_[k++];
      if (pf.fd >= 0 && pf.revents == 0)
        continue;  // nothing from this host (errors and hang-ups are read)
      if (const std::string rx = set_.endpoints[d][p]->PollHost(t_rx); !rx.empty()) {
        set_.devices[d]->OnHostBytes(static_cast<int>(p), t_rx, rx, out);
        set_.endpoints[d][p]->set_baud(set_.devices[d]->baud(static_cast<int>(p)));
        replied = replied || !out.serial.empty() || !out.can.empty();
        Dispatch(d, out);
      }
    }
  }
  // virtual mode: a reply goes to the host now, not after what the run may hold back
  if (!pacer_ && replied && !write_refused_ && !writes_.Pump(true)) write_refused_ = true;
  return replied;
}

bool Scheduler::PaceTowards(Time t_event, DeviceOutput& out) {
  // the next action in emulated time: a device event, a byte leaving a UART or a CAN frame
  std::optional<Time> t_byte;
  SerialEndpoint* ep_next = nullptr;
  for (auto& ports : set_.endpoints) {
    for (auto& ep : ports) {
      const auto tb = ep->next_byte_time();
      if (tb && (!t_byte || *tb < *t_byte)) {
        t_byte = tb;
        ep_next = ep.get();
      }
    }
  }
  const std::optional<Time> t_frame = set_.can ? set_.can->next_frame_time() : std::nullopt;
  if (t_frame && (!t_byte || *t_frame <= *t_byte) && (*t_frame < t_event || t_event > t_end_)) {
    set_.can->SendNext(*pacer_);
    return true;
  }
  if (ep_next && (*t_byte < t_event || t_event > t_end_)) {
    ep_next->WriteNextByte(*pacer_);
    PollHosts(*t_byte, out);  // a host's command arrives while the device talks
    return true;
  }
  if (t_event > t_end_) return false;
  // idle until the next event, but a host command is read when it arrives (within ~1 ms), not at
  // the next event: the device may answer in between
  const Time t_wake = std::min(
      t_event, pacer_->SimTimeOfWall(link::RealtimePacer::MonotonicNs()) + kHostPollPeriod);
  pacer_->SleepUntil(t_wake);
  return PollHosts(t_wake, out) || t_wake < t_event;
}

void Scheduler::Serve(Time t_event, const TruthSample& truth, SchedulerMonitor& monitor,
                      DeviceOutput& out) {
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    if (set_.devices[d]->next_event_time() != t_event) continue;
    set_.devices[d]->OnEvent(truth, out);
    Dispatch(d, out);
  }
  monitor.OnDeviceEvents(t_event);
  // configuration commands from the host reach the device with their arrival time
  PollHosts(t_event, out);
  t_last_event_ = t_event;
  PollBus();
}

void Scheduler::Run(SchedulerMonitor& monitor, const truth::TruthConfig* truth) {
  std::optional<truth::TruthIntegrator> integrator;
  if (truth) integrator.emplace(*truth);
  DeviceOutput out;
  for (;;) {
    std::optional<Time> t_event;
    for (const auto& dev : set_.devices) {
      if (!t_event || dev->next_event_time() < *t_event) t_event = dev->next_event_time();
    }
    if (!t_event) break;
    if (pacer_ && PaceTowards(*t_event, out)) continue;
    if (*t_event > t_end_) break;
    TruthSample sample;
    if (integrator) {
      sample = integrator->Sample(*t_event);
    } else {
      sample.t = *t_event;
    }
    Serve(*t_event, sample, monitor, out);
    if (write_refused_ || !monitor.KeepGoing(*t_event)) break;
  }
}

const std::vector<CanFrame>& Scheduler::PollBus() {
  if (set_.can) {
    const Time t_bus =
        pacer_ ? pacer_->SimTimeOfWall(link::RealtimePacer::MonotonicNs()) : t_last_event_;
    for (const CanFrame& f : set_.can->PollBus(t_bus)) bus_frames_.push_back(f);
  }
  return bus_frames_;
}

void Scheduler::Flush() {
  if (!pacer_) {
    if (!write_refused_ && !writes_.Pump(true)) write_refused_ = true;
    return;
  }
  for (auto& ports : set_.endpoints) {
    for (auto& ep : ports) {
      while (ep->next_byte_time()) ep->WriteNextByte(*pacer_);
    }
  }
  if (set_.can) {
    while (set_.can->next_frame_time()) set_.can->SendNext(*pacer_);
  }
}

}  // namespace hil::harness

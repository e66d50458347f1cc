#include "hil/harness/run/scheduler.h"

#include <poll.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "hil/truth/truth_integrator.h"

namespace hil::harness {
namespace {

/// In real time, how long (wall) the event thread sleeps at most before it looks for host bytes
/// again.
constexpr std::int64_t kHostPollPeriodNs = 1'000'000;
/// In real time, how long (wall) before its time an event is computed, so that its bytes wait in
/// their queues when the pacing thread is due to write them (a host command read meanwhile counts
/// from that event's time on: it takes effect at most this much later than it arrived).
constexpr std::int64_t kEventLeadNs = 5'000'000;

}  // namespace

Scheduler::Scheduler(const Scenario& scenario, DeviceSet& devices, ByteFaultInjector& faults,
                     const link::RealtimePacer* pacer, std::ostream& fixes_csv)
    : scenario_(scenario), set_(devices), faults_(faults), pacer_(pacer), fixes_csv_(fixes_csv) {}

Scheduler::~Scheduler() = default;

std::unique_lock<std::mutex> Scheduler::LinksLock() {
  return pacing_ ? std::unique_lock<std::mutex>(pacing_->links_mutex())
                 : std::unique_lock<std::mutex>();
}

void Scheduler::StartPacing() {
  std::vector<SerialEndpoint*> serial;
  for (auto& ports : set_.endpoints) {
    for (auto& ep : ports) serial.push_back(ep.get());
  }
  pacing_ = std::make_unique<PacingThread>(serial, set_.can.get(), *pacer_);
  set_.threads = {{"events", link::RealtimePacer::CurrentThreadSchedule()},
                  {"pacing", pacing_->schedule()}};
}

void Scheduler::Dispatch(std::size_t d, DeviceOutput& out) {
  std::unique_lock<std::mutex> lock = LinksLock();
  std::vector<SerialMessage> carried;
  for (SerialMessage& m : out.serial) {
    SerialEndpoint& ep = *set_.endpoints[d].at(static_cast<std::size_t>(m.port));
    carried.clear();
    faults_.Process(m, ep.link_name(), ep.uart().baud(), carried);
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
    faults_.ProcessCan(out.can);
    for (const CanFrame& f : out.can) set_.can->Queue(f);
  }
  out.clear();
  if (!pacer_) {
    if (!write_refused_ && !writes_.Pump(false)) write_refused_ = true;
    if (set_.can) set_.can->SendAll();
  }
  if (pacing_) {
    lock.unlock();
    pacing_->Wake();
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
    // real time: its arrival, but not before the event the devices already computed
    const Time t_rx =
        pacer_ ? std::max(pacer_->SimTimeOfWall(link::RealtimePacer::MonotonicNs()), t_last_event_)
               : t_host;
    for (std::size_t p = 0; p < set_.endpoints[d].size(); ++p) {
      const pollfd& pf = host_fds_[k++];
      if (pf.fd >= 0 && pf.revents == 0)
        continue;  // nothing from this host (errors and hang-ups are read)
      std::string rx;
      {
        const std::unique_lock<std::mutex> lock = LinksLock();
        rx = set_.endpoints[d][p]->PollHost(t_rx, !pacer_);
      }
      if (!rx.empty()) {
        set_.devices[d]->OnHostBytes(static_cast<int>(p), t_rx, rx, out);
        {
          const std::unique_lock<std::mutex> lock = LinksLock();
          set_.endpoints[d][p]->set_baud(set_.devices[d]->baud(static_cast<int>(p)));
        }
        replied = replied || !out.serial.empty() || !out.can.empty();
        Dispatch(d, out);
      }
    }
  }
  // virtual mode: a reply goes to the host now, not after what the run may hold back
  if (!pacer_ && replied && !write_refused_ && !writes_.Pump(true)) write_refused_ = true;
  return replied;
}

void Scheduler::RecordFixes(Time t) {
  // the raw-GNSS baseline is one receiver, the first (its antenna is the scenario's antenna lever
  // arm); further receivers of a multi-antenna scenario feed the estimator, not the baseline
  if (set_.fix_sources.empty()) return;
  {
    const gnss::GnssFix& fix = *set_.fix_sources.front()();
    if (fix.t_validity != t) return;
    if (recorder_) {
      const auto outage = recorder_->Active(FaultKind::kGnssOutage, t);
      if (outage && !fix.valid()) recorder_->Note(*outage, t);
      const auto gap = recorder_->Active(FaultKind::kGnssDataGap, t);
      if (gap) recorder_->Note(*gap, t);  // the receiver computed this epoch but sent nothing
      const auto glitch = recorder_->Active(FaultKind::kGnssGlitch, t);
      if (glitch && fix.valid()) recorder_->Note(*glitch, t);
    }
    if (!fix.valid()) return;
    EstimateRecord r;
    r.t_validity = fix.t_validity;
    r.lat_deg = fix.lat_deg;
    r.lon_deg = fix.lon_deg;
    r.height_m = fix.height_m;
    r.vel_enu_mps = Eigen::Vector3d(fix.vel_e_mps, fix.vel_n_mps, -fix.vel_d_mps);
    fixes_.push_back(r);
    char line[256];
    std::snprintf(line, sizeof line, "%.3f,%.9f,%.9f,%.4f,%.4f,%.4f,%.4f,%d,%.2f\n",
                  ToSeconds(fix.t_validity), fix.lat_deg, fix.lon_deg, fix.height_m, fix.vel_n_mps,
                  fix.vel_e_mps, fix.vel_d_mps, fix.num_sv, fix.hdop);
    fixes_csv_ << line;
  }
}

void Scheduler::Run(const std::function<bool(Time)>& keep_going) {
  bool to_the_end = false;
  try {
    to_the_end = RunEvents(keep_going);
  } catch (...) {
    pacing_.reset();  // a run that failed writes nothing more
    throw;
  }
  if (!to_the_end) pacing_.reset();  // stopped early: what is queued stays unsent
}

bool Scheduler::RunEvents(const std::function<bool(Time)>& keep_going) {
  truth::TruthIntegrator truth(scenario_.truth);
  const Time t_end = TimeFromSeconds(scenario_.duration_s);
  DeviceOutput out;
  for (;;) {
    // the next action in emulated time: a device event or (real time) a byte leaving a UART
    std::optional<Time> t_event;
    for (const auto& dev : set_.devices) {
      if (!t_event || dev->next_event_time() < *t_event) t_event = dev->next_event_time();
    }
    if (!t_event) return true;
    if (pacer_) {
      // the pacing thread writes the bytes and frames; this one idles until the next event, but
      // reads a host command when it arrives (within ~1 ms), not at the next event: the device
      // may answer in between
      if (!pacing_) StartPacing();
      const std::int64_t now = link::RealtimePacer::MonotonicNs();
      const std::int64_t due = pacer_->WallNsOf(*t_event) - kEventLeadNs;
      if (*t_event <= t_end && due > now) {
        std::this_thread::sleep_until(std::chrono::steady_clock::time_point(
            std::chrono::nanoseconds(std::min(due, now + kHostPollPeriodNs))));
        PollHosts(*t_event, out);
        continue;
      }
    }
    if (gate_ && !pacer_) {
      // host bytes arriving, then a host turn, due before (or at) this event come first
      if (!arrivals_.empty() && arrivals_.front().t <= std::min(*t_event, t_end)) {
        DeliverHostBytes(arrivals_.front(), out);
        arrivals_.pop_front();
        continue;
      }
      const Time t_turn = NextHostTurn();
      if (t_turn <= *t_event && t_turn <= t_end) {
        HostTurn(t_turn);
        if (write_refused_) return false;
        continue;
      }
    }
    if (*t_event > t_end) return true;
    const TruthSample ts = truth.Sample(*t_event);
    for (std::size_t d = 0; d < set_.devices.size(); ++d) {
      if (set_.devices[d]->next_event_time() != *t_event) continue;
      set_.devices[d]->OnEvent(ts, out);
      Dispatch(d, out);
    }
    RecordFixes(*t_event);
    t_last_event_ = *t_event;
    // real time: configuration commands from the host reach the device with their arrival time
    // (virtual mode reads them at host turns); without a gate no host is paced and none is waited
    // for
    if (pacer_ || !gate_) PollHosts(*t_event, out);
    PollBus();
    if (write_refused_ || !keep_going(*t_event)) return false;
  }
}

Time Scheduler::NextHostTurn() const {
  Time t = next_periodic_turn_;
  for (const Time a : answer_turns_) t = std::min(t, a);
  return t;
}

void Scheduler::HostTurn(Time t) {
  while (next_periodic_turn_ <= t) next_periodic_turn_ += kHostTurnPeriod;
  std::erase_if(answer_turns_, [t](Time a) { return a <= t; });
  if (!writes_.Pump(true) || !gate_->WaitHostIdle()) {
    write_refused_ = true;
    return;
  }
  // What the host wrote may answer any byte written so far (virtual mode writes bytes when they
  // are made, ahead of their UART times): it arrives once the last of them has left its UART.
  Time t_rx = t;
  for (const auto& ports : set_.endpoints) {
    for (const auto& ep : ports) t_rx = std::max(t_rx, ep->last_queued_end());
  }
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    for (std::size_t p = 0; p < set_.endpoints[d].size(); ++p) {
      std::string rx = set_.endpoints[d][p]->PollHost(t_rx, true);
      if (!rx.empty()) arrivals_.push_back({t_rx, d, p, std::move(rx)});
    }
  }
}

void Scheduler::DeliverHostBytes(const HostBytes& h, DeviceOutput& out) {
  const int port = static_cast<int>(h.port);
  set_.devices[h.device]->OnHostBytes(port, h.t, h.bytes, out);
  SerialEndpoint& ep = *set_.endpoints[h.device][h.port];
  ep.set_baud(set_.devices[h.device]->baud(port));
  const bool answered = !out.serial.empty();
  Dispatch(h.device, out);
  if (!write_refused_ && !writes_.Pump(true)) write_refused_ = true;
  // the host's next turn: when the answer has left the UART (it is written at once)
  if (answered) {
    for (const auto& e : set_.endpoints[h.device]) {
      if (e->last_queued_end() > h.t) answer_turns_.push_back(e->last_queued_end());
    }
  }
}

const std::vector<CanFrame>& Scheduler::PollBus() {
  if (set_.can) {
    const Time t_bus =
        pacer_ ? pacer_->SimTimeOfWall(link::RealtimePacer::MonotonicNs()) : t_last_event_;
    const std::unique_lock<std::mutex> lock = LinksLock();
    for (const CanFrame& f : set_.can->PollBus(t_bus, pacer_)) bus_frames_.push_back(f);
  }
  return bus_frames_;
}

void Scheduler::Flush() {
  if (!pacer_) {
    if (!write_refused_ && !writes_.Pump(true)) write_refused_ = true;
    return;
  }
  if (pacing_) {
    pacing_->Drain();  // every byte and frame still queued leaves at its time
    pacing_.reset();
  }
  if (set_.can) {
    set_.can->FinishCapture(std::chrono::milliseconds(100));  // the last frames' echoes
    PollBus();
  }
}

}  // namespace hil::harness

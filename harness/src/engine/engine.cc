#include "hil/harness/engine/engine.h"

#include <poll.h>

#include <algorithm>
#include <chrono>
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

Scheduler::Scheduler(DeviceSet& devices, const link::RealtimePacer* pacer, Time t_end)
    : set_(devices), pacer_(pacer), t_end_(t_end) {}

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
  events_cpu_start_ = link::ThreadCpuReading::Now();
  pacing_ = std::make_unique<PacingThread>(serial, set_.can.get(), *pacer_);
  set_.threads = {{"events", link::RealtimePacer::CurrentThreadSchedule()},
                  {"pacing", pacing_->schedule()}};
  set_.cpu_at_start = ReadCpuTicks();
}

void Scheduler::EndPacing(bool drain) {
  if (!pacing_) return;
  if (drain) {
    pacing_->Drain();
  } else {
    pacing_->Stop();
  }
  for (auto& [name, schedule] : set_.threads) {
    if (name == "events") schedule.usage = link::ThreadCpuReading::Now().Since(events_cpu_start_);
    if (name == "pacing") schedule.usage = pacing_->usage();
  }
  pacing_.reset();
}

void Scheduler::Dispatch(std::size_t d, DeviceOutput& out) {
  std::unique_lock<std::mutex> lock = LinksLock();
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
        if (pacer_) continue;
        if (gate_ && control_period_ > Duration{} && Actuator(d)) {
          held_.push_back({&ep, c.bytes.size(), c.t_ready});  // to the controller at a turn
        } else {
          writes_.Add(ep, c.bytes.size(), c.t_ready);
        }
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
    // a paced host reads its links in runs of messages (VirtualWriteQueue); CAN frames are not
    // paced, so beside a bus every serial chunk goes as soon as it may, as the frames do
    const bool hold_tail = gate_ && !set_.can;
    if (!write_refused_ && !writes_.Pump(false, hold_tail)) write_refused_ = true;
    if (set_.can) set_.can->SendAll();
  }
  if (pacing_) {
    lock.unlock();
    pacing_->Wake();
  }
}

void Scheduler::PollHostFds() {
  // one poll() for every port instead of a read() each: hosts rarely write
  if (host_fds_.empty()) {
    for (const auto& ports : set_.endpoints) {
      for (const auto& ep : ports) host_fds_.push_back({ep->host_input_fd(), POLLIN, 0});
    }
  }
  for (pollfd& p : host_fds_) p.revents = 0;
  poll(host_fds_.data(), host_fds_.size(), 0);
}

bool Scheduler::HostWrote() {
  PollHostFds();
  return std::any_of(host_fds_.begin(), host_fds_.end(),
                     [](const pollfd& p) { return p.fd >= 0 && (p.revents & POLLIN) != 0; });
}

bool Scheduler::PollHosts(Time t_host, DeviceOutput& out) {
  PollHostFds();
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

bool Scheduler::PaceTowards(Time t_event, DeviceOutput& out) {
  // the pacing thread writes the bytes and frames; this one idles until the next event, but reads
  // a host command when it arrives (within ~1 ms), not at the next event: the device may answer
  // in between
  const std::int64_t now = link::RealtimePacer::MonotonicNs();
  const std::int64_t due = pacer_->WallNsOf(t_event) - kEventLeadNs;
  if (t_event > t_end_ || due <= now) return false;
  std::this_thread::sleep_until(std::chrono::steady_clock::time_point(
      std::chrono::nanoseconds(std::min(due, now + kHostPollPeriodNs))));
  PollHosts(t_event, out);
  return true;
}

void Scheduler::PaceLockstep(Time t_event) {
  Time t = std::min(t_event, t_end_);
  if (!arrivals_.empty()) t = std::min(t, arrivals_.front().t);
  if (!bus_arrivals_.empty()) t = std::min(t, bus_arrivals_.front().t);
  if (gate_) t = std::min(t, NextHostTurn());
  const std::int64_t due = lockstep_pace_->WallNsOf(t);
  const std::int64_t now = link::RealtimePacer::MonotonicNs();
  ++lateness_.actions;
  if (due > now) {
    std::this_thread::sleep_until(
        std::chrono::steady_clock::time_point(std::chrono::nanoseconds(due)));
    return;
  }
  if (now - due > 1'000'000) ++lateness_.late;
  lateness_.max_late_ns = std::max(lateness_.max_late_ns, now - due);
}

bool Scheduler::HostStep(Time t_event, SchedulerMonitor& monitor, DeviceOutput& out) {
  // host bytes arriving, then a host turn, due before (or at) this event come first
  if (!arrivals_.empty() && arrivals_.front().t <= std::min(t_event, t_end_)) {
    DeliverHostBytes(arrivals_.front(), out);
    arrivals_.pop_front();
    return true;
  }
  if (!bus_arrivals_.empty() && bus_arrivals_.front().t <= std::min(t_event, t_end_)) {
    DeliverBusFrame(bus_arrivals_.front().t, bus_arrivals_.front().frame, out);
    bus_arrivals_.pop_front();
    return true;
  }
  const Time t_turn = NextHostTurn();
  if (t_turn > t_event || t_turn > t_end_) return false;
  if (ControlTickAnswered(t_turn) && !monitor.ActsAtTurn(t_turn)) {
    ++skipped_control_turns_;
    while (next_control_turn_ <= t_turn) next_control_turn_ += control_period_;
    return true;
  }
  HostTurn(t_turn);
  if (!write_refused_) monitor.OnHostTurn(t_turn);
  return true;
}

void Scheduler::Serve(Time t_event, const TruthSample& truth, SchedulerMonitor& monitor,
                      DeviceOutput& out) {
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    if (set_.devices[d]->next_event_time() != t_event) continue;
    if (ahead_) last_event_[d] = t_event;
    set_.devices[d]->OnEvent(truth, out);
    if (const std::optional<VehicleCommand> c = set_.devices[d]->TakeVehicleCommand()) {
      if (integrator_) integrator_->SetCommand(c->t, c->speed_mps, c->steer_or_yaw_rate);
      vehicle_commands_.push_back(*c);
    }
    Dispatch(d, out);
  }
  monitor.OnDeviceEvents(t_event);
  t_last_event_ = t_event;
  // real time: configuration commands from the host reach the device with their arrival time
  // (virtual mode reads them at host turns); without a gate no host is paced and none is waited
  // for
  if (pacer_ || !gate_) PollHosts(t_event, out);
  PollBus();
  if (pacer_ && set_.steering) RouteBusFrames(t_event, out);
}

void Scheduler::Run(SchedulerMonitor& monitor, const truth::TruthConfig* truth) {
  bool to_the_end = false;
  try {
    to_the_end = RunEvents(monitor, truth);
  } catch (...) {
    EndPacing(false);  // a run that failed writes nothing more
    throw;
  }
  if (!to_the_end) EndPacing(false);  // stopped early: what is queued stays unsent
}

bool Scheduler::RunEvents(SchedulerMonitor& monitor, const truth::TruthConfig* truth) {
  std::optional<truth::TruthIntegrator>& integrator = integrator_;
  // virtual mode, open loop: the truth is a function of time alone, sampled ahead on a thread
  if (truth && !pacer_ && !truth->external_commands) {
    ahead_.emplace(*truth);
    schedule_.resize(set_.devices.size());
    last_event_.resize(set_.devices.size());
  } else if (truth) {
    integrator.emplace(*truth);
  }
  if (pacer_ && !pacing_) StartPacing();  // before the first event: its bytes leave on time
  DeviceOutput out;
  for (;;) {
    std::optional<Time> t_event;
    for (const auto& dev : set_.devices) {
      if (!t_event || dev->next_event_time() < *t_event) t_event = dev->next_event_time();
    }
    if (!t_event) return true;
    if (pacer_ && PaceTowards(*t_event, out)) continue;
    if (lockstep_pace_) PaceLockstep(*t_event);
    if (gate_ && !pacer_ && HostStep(*t_event, monitor, out)) {
      if (write_refused_) return false;
      continue;
    }
    if (*t_event > t_end_) return true;
    TruthSample sample;
    if (ahead_ || integrator) {
      sample = ahead_ ? AheadSample(*t_event) : integrator->Sample(*t_event);
    } else {
      sample.t = *t_event;
    }
    Serve(*t_event, sample, monitor, out);
    // closed loop: a command the event gave that acts at its instant (the first, at t = 0)
    // re-integrates the truth, and the sample taken before it is not the truth's any more
    if (truth_tap_ && (ahead_ || integrator) && !(integrator && integrator->restart_pending()))
      truth_tap_(sample);
    // lockstep: what the event made leaves now, at its time (virtual mode may hold it back)
    if (lockstep_pace_ && !write_refused_ && !writes_.Pump(true)) write_refused_ = true;
    if (write_refused_ || !monitor.KeepGoing(*t_event)) return false;
  }
}

TruthSample Scheduler::AheadSample(Time t) {
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    const Time next = set_.devices[d]->next_event_time();
    const Duration period = last_event_[d] ? next - *last_event_[d] : Duration{};
    schedule_[d] = {next, period > Duration{0} ? period : Duration{}};
  }
  ahead_->Plan(schedule_);
  return ahead_->Sample(t);
}

Time Scheduler::NextHostTurn() const {
  Time t = next_periodic_turn_;
  if (control_period_ > Duration{}) t = std::min(t, next_control_turn_);
  for (const Time a : answer_turns_) t = std::min(t, a);
  return t;
}

bool Scheduler::ControlTickAnswered(Time t) const {
  if (control_period_ == Duration{} || next_control_turn_ != t || next_periodic_turn_ <= t)
    return false;
  if (std::any_of(answer_turns_.begin(), answer_turns_.end(), [t](Time a) { return a <= t; }))
    return false;
  return !arrivals_.empty();
}

void Scheduler::HostTurn(Time t) {
  while (next_periodic_turn_ <= t) next_periodic_turn_ += kHostTurnPeriod;
  if (control_period_ > Duration{}) {
    while (next_control_turn_ <= t) next_control_turn_ += control_period_;
  }
  std::erase_if(answer_turns_, [t](Time a) { return a <= t; });
  // An open-loop host holding its links read-only has nothing for a turn to read: no wait (each
  // one cost the host's backlog of work, seed004 0.5 s of 2.9). Bytes from it all the same (it
  // opened a link for writing later) end that.
  if (control_period_ == Duration{} && gate_->HostReadsOnly()) {
    if (!HostWrote()) return;
    gate_->NoteHostWrote();
  }
  if (!writes_.Pump(true) || !gate_->WaitHostIdle()) {
    write_refused_ = true;
    return;
  }
  // The actuators' replies and status reach the controller now, with the host asleep: which of
  // them it has read when a solution makes it compute a command does not depend on the machine
  // (written when made, a status frame could be read before or after the solution that came
  // meanwhile; guidanced's reset request after an ECU exit then went out one command early or
  // late in some runs).
  if (!held_.empty()) {
    ReleaseHeld();
    if (!writes_.Pump(true)) {
      write_refused_ = true;
      return;
    }
  }
  // What the host wrote may answer any byte it has read (virtual mode writes bytes when they are
  // made, ahead of their UART times): it arrives once the last of them has left its UART. Links
  // the host does not read do not count (paper 003's UWB navd leaves the 9600 Bd GNSS link
  // unread: its NMEA epochs held a controller's commands back by up to 0.66 s).
  Time t_rx = t;
  for (const auto& ports : set_.endpoints) {
    for (const auto& ep : ports) {
      if (gate_->Reads(*ep)) t_rx = std::max(t_rx, ep->last_queued_end());
    }
  }
  PollHostFds();  // one poll() instead of a read() per port (it hands over bytes in flight too)
  std::size_t k = 0;
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    for (std::size_t p = 0; p < set_.endpoints[d].size(); ++p) {
      const pollfd& pf = host_fds_[k++];
      if (pf.fd >= 0 && pf.revents == 0) continue;  // nothing from the host on this port
      std::string rx = set_.endpoints[d][p]->PollHost(t_rx, true);
      if (!rx.empty()) arrivals_.push_back({t_rx, d, p, std::move(rx)});
    }
  }
  if (!set_.steering) return;  // nothing listens to the bus: open-loop runs read it as before
  PollBus();
  // the controller's frames arrive now: the capture says so (read between turns, they would be
  // stamped whenever the run happened to look)
  if (set_.can) {
    const std::unique_lock<std::mutex> lock = LinksLock();
    for (const CanFrame& f : set_.can->TakeArrivals(t_rx)) bus_frames_.push_back(f);
  }
  DeviceOutput none;
  RouteBusFrames(t_rx, none);
}

void Scheduler::RouteBusFrames(Time t_rx, DeviceOutput& out) {
  for (; bus_routed_ < bus_frames_.size(); ++bus_routed_) {
    const CanFrame& f = bus_frames_[bus_routed_];
    if (pacer_) {
      DeliverBusFrame(std::max(f.t, t_last_event_), f, out);
    } else {
      bus_arrivals_.push_back({t_rx, f});
    }
  }
}

void Scheduler::DeliverBusFrame(Time t, const CanFrame& frame, DeviceOutput& out) {
  for (std::size_t d = 0; d < set_.devices.size(); ++d) {
    set_.devices[d]->OnBusFrame(t, frame, out);
    Dispatch(d, out);
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

bool Scheduler::Actuator(std::size_t d) const {
  const Device* dev = set_.devices[d].get();
  return dev == set_.base || dev == set_.steering;
}

void Scheduler::ReleaseHeld() {
  for (const Held& h : held_) writes_.Add(*h.ep, h.bytes, h.t);
  held_.clear();
}

void Scheduler::Flush() {
  if (!pacer_) {
    ReleaseHeld();
    if (!write_refused_ && !writes_.Pump(true)) write_refused_ = true;
    return;
  }
  EndPacing(true);  // every byte and frame still queued leaves at its time
  if (set_.can) {
    set_.can->FinishCapture(std::chrono::milliseconds(100));  // the last frames' echoes
    PollBus();
  }
}

}  // namespace hil::harness

#include "hil/harness/engine/engine.h"

#include <algorithm>

namespace hil::harness {

Engine::Engine(EngineDevices devices, Pacer& pacer, std::unique_ptr<HostTurns> turns, Time t_end)
    : pacer_(pacer),
      turns_(std::move(turns)),
      io_(devices, pacer, turns_->holds_actuator_bytes()),
      t_end_(t_end),
      truth_(MakeTruthSource(nullptr, pacer.stepping(), 0)) {}

void Engine::Run(EngineMonitor& monitor, const truth::TruthConfig* truth) {
  bool to_the_end = false;
  try {
    to_the_end = RunEvents(monitor, truth);
  } catch (...) {
    pacer_.End(false);  // a run that failed writes nothing more
    throw;
  }
  if (!to_the_end) pacer_.End(false);  // stopped early: what is queued stays unsent
}

std::optional<Time> Engine::NextEvent() const {
  std::optional<Time> t_event;
  for (const auto& dev : io_.devices().devices) {
    if (!t_event || dev->next_event_time() < *t_event) t_event = dev->next_event_time();
  }
  return t_event;
}

bool Engine::RunEvents(EngineMonitor& monitor, const truth::TruthConfig* truth) {
  truth_ = MakeTruthSource(truth, pacer_.stepping(), io_.devices().devices.size());
  pacer_.Start(io_.devices());  // before the first event: its bytes leave on time
  DeviceOutput out;
  for (;;) {
    const std::optional<Time> t_event = NextEvent();
    if (!t_event) return true;
    const StepTimes step{*t_event, t_end_, std::min({*t_event, t_end_, turns_->NextAction()})};
    if (pacer_.Await(step, io_, out)) continue;
    if (turns_->BeforeEvent(*t_event, t_end_, monitor, io_, out)) {
      if (io_.refused()) return false;
      continue;
    }
    if (*t_event > t_end_) return true;
    const TruthSample x = truth_->Sample(*t_event, io_.devices().devices);
    // a late command re-integrates the truth: x, taken before it, is not offered
    const bool late = Serve(*t_event, x, monitor, out);
    if (truth_->sample_is_truth() && !late) truth_tap_(x);
    pacer_.EndOfStep(io_);
    if (io_.refused() || !monitor.KeepGoing(*t_event)) return false;
  }
}

bool Engine::Serve(Time t_event, const TruthSample& x, EngineMonitor& monitor, DeviceOutput& out) {
  const auto& devices = io_.devices().devices;
  bool any_late = false;
  for (std::size_t d = 0; d < devices.size(); ++d) {
    if (devices[d]->next_event_time() != t_event) continue;
    truth_->Served(d, t_event);
    devices[d]->OnEvent(x, out);
    if (const std::optional<VehicleCommand> c = devices[d]->TakeVehicleCommand()) {
      const long restarts = truth_->late_command_restarts();
      truth_->Command(*c);
      const bool late = truth_->late_command_restarts() > restarts;
      any_late = any_late || late;
      command_tap_(*c, late);
    }
    io_.Dispatch(d, out);
  }
  monitor.OnDeviceEvents(t_event);
  io_.set_t_last_event(t_event);
  turns_->AfterEvent(t_event, io_, out);
  io_.PollBus();
  pacer_.RouteBusFrames(io_, out);
  return any_late;
}

void Engine::Flush() {
  io_.ReleaseHeld();
  if (!pacer_.Flush(io_) || !turns_->Drain(io_)) io_.Refuse();
}

}  // namespace hil::harness

#include "hil/harness/engine/wall_clock_pacer.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "hil/harness/engine/device_io.h"

namespace hil::harness {

WallClockPacer::~WallClockPacer() = default;

void WallClockPacer::Start(EngineDevices& devices) {
  std::vector<SerialEndpoint*> serial;
  for (auto& ports : devices.endpoints) {
    for (auto& ep : ports) serial.push_back(ep.get());
  }
  events_cpu_start_ = link::ThreadCpuReading::Now();
  pacing_ = std::make_unique<PacingThread>(serial, devices.can, clock_);
  threads_ = {{"events", link::RealtimePacer::CurrentThreadSchedule()},
              {"pacing", pacing_->schedule()}};
}

void WallClockPacer::End(bool drain) {
  if (!pacing_) return;  // ended already (or never started)
  if (drain) {
    pacing_->Drain();
  } else {
    pacing_->Stop();
  }
  for (auto& [name, schedule] : threads_) {
    if (name == "events") schedule.usage = link::ThreadCpuReading::Now().Since(events_cpu_start_);
    if (name == "pacing") schedule.usage = pacing_->usage();
  }
  pacing_.reset();
}

std::unique_lock<std::mutex> WallClockPacer::LinksLock() {
  return pacing_ ? std::unique_lock<std::mutex>(pacing_->links_mutex())
                 : std::unique_lock<std::mutex>();
}

std::optional<WallTime> WallClockPacer::Wake(Time t_event, Time t_end, WallTime now) const {
  const WallTime due = clock_.WallTimeOf(t_event) - kEventLead;
  if (t_event > t_end || due <= now) return std::nullopt;
  return std::min(due, now + kHostPollPeriod);
}

bool WallClockPacer::Await(const StepTimes& step, DeviceIo& io, DeviceOutput& out) {
  // the pacing thread writes the bytes and frames; this one idles until the next event, but reads
  // a host command when it arrives (within ~1 ms), not at the next event: the device may answer
  // in between
  const std::optional<WallTime> wake = Wake(step.t_event, step.t_end, WallNow());
  if (!wake) return false;
  std::this_thread::sleep_until(ToSteady(*wake));
  io.PollHosts(step.t_event, out);
  return true;
}

bool WallClockPacer::Send(CanEndpoint* can, bool write, std::unique_lock<std::mutex>& lock) {
  (void)can, (void)write;
  if (pacing_) {
    lock.unlock();
    pacing_->Wake();
  }
  return true;
}

bool WallClockPacer::Flush(DeviceIo& io) {
  End(true);  // every byte and frame still queued leaves at its time
  if (CanEndpoint* can = io.devices().can) {
    can->FinishCapture(std::chrono::milliseconds(100));  // the last frames' echoes
    io.PollBus();
  }
  return true;
}

Time WallClockPacer::ArrivalTime(WallTime now, Time t_last_event) const {
  return std::max(clock_.SimTimeOfWall(now), t_last_event);
}

Time WallClockPacer::HostBytesTime(Time t_host, Time t_last_event) const {
  (void)t_host;  // real time: its arrival, but not before the event the devices computed
  return ArrivalTime(WallNow(), t_last_event);
}

Time WallClockPacer::BusTime(Time t_last_event) const {
  (void)t_last_event;
  return clock_.SimTimeOfWall(WallNow());
}

void WallClockPacer::RouteBusFrames(DeviceIo& io, DeviceOutput& out) {
  // taken even when nothing listens to the bus, so that the frames do not pile up (issue 40)
  const std::vector<CanFrame> frames = io.TakeUnrouted();
  if (!io.devices().steering) return;  // nothing listens to the bus
  for (const CanFrame& f : frames) io.DeliverBusFrame(std::max(f.t, io.t_last_event()), f, out);
}

}  // namespace hil::harness

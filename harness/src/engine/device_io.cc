#include "hil/harness/engine/device_io.h"

#include <algorithm>
#include <string>
#include <utility>

namespace hil::harness {

DeviceIo::DeviceIo(EngineDevices devices, Pacer& pacer, bool hold_actuators)
    : devices_(devices), pacer_(pacer), hold_actuators_(hold_actuators) {}

void DeviceIo::QueueMessage(std::size_t d, SerialEndpoint& ep, const SerialMessage& m) {
  if (ep.Queue(m)) {
    if (hold_actuators_ && Actuator(d)) {
      held_.push_back({&ep, m.bytes.size(), m.t_ready});  // to the controller at a turn
    } else {
      pacer_.Queued(ep, m.bytes.size(), m.t_ready);
    }
    return;
  }
  if (!recorder_) return;
  // the receiver's transmit buffer overflowed: count it against an active output overload
  if (const auto i = recorder_->Active(FaultKind::kGnssOverload, m.t_ready))
    recorder_->Note(*i, m.t_ready);
}

void DeviceIo::Dispatch(std::size_t d, DeviceOutput& out) {
  std::unique_lock<std::mutex> lock = pacer_.LinksLock();
  for (SerialMessage& m : out.serial) {
    SerialEndpoint& ep = *devices_.endpoints[d].at(static_cast<std::size_t>(m.port));
    carried_.clear();
    if (faults_) {
      faults_->Process(m, ep.link_name(), ep.uart().baud(), carried_);
    } else {
      carried_.push_back(m);
    }
    for (const SerialMessage& c : carried_) QueueMessage(d, ep, c);
  }
  if (devices_.can) {
    if (faults_) faults_->ProcessCan(out.can);
    const bool hold = hold_actuators_ && Actuator(d);  // to the controller at a turn, as bytes are
    for (const CanFrame& f : out.can) {
      if (hold) {
        held_frames_.push_back(f);
      } else {
        devices_.can->Queue(f);
      }
    }
  }
  out.clear();
  if (!pacer_.Send(devices_.can, !refused_, lock)) refused_ = true;
}

void DeviceIo::PollHostFds() {
  // one poll() for every port instead of a read() each: hosts rarely write
  if (host_fds_.empty()) {
    for (const auto& ports : devices_.endpoints) {
      for (const auto& ep : ports) host_fds_.push_back({ep->host_input_fd(), POLLIN, 0});
    }
  }
  for (pollfd& p : host_fds_) p.revents = 0;
  poll(host_fds_.data(), host_fds_.size(), 0);
}

bool DeviceIo::HostWrote() {
  PollHostFds();
  return std::any_of(host_fds_.begin(), host_fds_.end(),
                     [](const pollfd& p) { return p.fd >= 0 && (p.revents & POLLIN) != 0; });
}

bool DeviceIo::PollHosts(Time t_host, DeviceOutput& out) {
  PollHostFds();
  bool replied = false;
  std::size_t k = 0;
  for (std::size_t d = 0; d < devices_.devices.size(); ++d) {
    const Time t_rx = pacer_.HostBytesTime(t_host, t_last_event_);
    for (std::size_t p = 0; p < devices_.endpoints[d].size(); ++p) {
      const pollfd& pf = host_fds_[k++];
      if (pf.fd >= 0 && pf.revents == 0)
        continue;  // nothing from this host (errors and hang-ups are read)
      std::string rx;
      {
        const std::unique_lock<std::mutex> lock = pacer_.LinksLock();
        rx = devices_.endpoints[d][p]->PollHost(t_rx, pacer_.host_bytes_virtual());
      }
      if (rx.empty()) continue;
      devices_.devices[d]->OnHostBytes(static_cast<int>(p), t_rx, rx, out);
      {
        const std::unique_lock<std::mutex> lock = pacer_.LinksLock();
        devices_.endpoints[d][p]->set_baud(devices_.devices[d]->baud(static_cast<int>(p)));
      }
      replied = replied || !out.serial.empty() || !out.can.empty();
      Dispatch(d, out);
    }
  }
  // virtual writes: a reply goes to the host now, not after what the run may hold back
  if (replied) SendAll();
  return replied;
}

void DeviceIo::PollBus() {
  if (!devices_.can) return;
  const Time t_bus = pacer_.BusTime(t_last_event_);
  const std::unique_lock<std::mutex> lock = pacer_.LinksLock();
  for (const CanFrame& f : devices_.can->PollBus(t_bus, pacer_.bus_stamp_clock()))
    bus_frames_.push_back(f);
}

std::vector<CanFrame> DeviceIo::TakeUnrouted() {
  std::vector<CanFrame> frames(bus_frames_.begin() + static_cast<std::ptrdiff_t>(bus_routed_),
                               bus_frames_.end());
  bus_routed_ = bus_frames_.size();
  DropTakenBusFrames();
  return frames;
}

std::vector<CanFrame> DeviceIo::TakeUncollected() {
  const std::size_t from = bus_collected_.value_or(0);
  std::vector<CanFrame> frames(bus_frames_.begin() + static_cast<std::ptrdiff_t>(from),
                               bus_frames_.end());
  bus_collected_ = bus_frames_.size();
  DropTakenBusFrames();
  return frames;
}

void DeviceIo::DropTakenBusFrames() {
  const std::size_t taken = std::min(bus_routed_, bus_collected_.value_or(bus_routed_));
  if (taken == 0) return;
  bus_frames_.erase(bus_frames_.begin(), bus_frames_.begin() + static_cast<std::ptrdiff_t>(taken));
  bus_routed_ -= taken;
  if (bus_collected_) *bus_collected_ -= taken;
}

void DeviceIo::DeliverBusFrame(Time t, const CanFrame& frame, DeviceOutput& out) {
  for (std::size_t d = 0; d < devices_.devices.size(); ++d) {
    devices_.devices[d]->OnBusFrame(t, frame, out);
    Dispatch(d, out);
  }
}

bool DeviceIo::Actuator(std::size_t d) const {
  const Device* dev = devices_.devices[d].get();
  return dev == devices_.base || dev == devices_.steering;
}

bool DeviceIo::ReleaseHeld() {
  if (held_.empty() && held_frames_.empty()) return false;
  for (const Held& h : held_) pacer_.Queued(*h.ep, h.bytes, h.t);
  held_.clear();
  if (held_frames_.empty()) return true;
  std::unique_lock<std::mutex> lock = pacer_.LinksLock();
  for (const CanFrame& f : held_frames_) devices_.can->Queue(f);  // in time order: Queue merges
  held_frames_.clear();
  frames_released_ = true;
  if (!pacer_.Send(devices_.can, false, lock)) refused_ = true;  // the frames only: see SendAll
  return true;
}

bool DeviceIo::AwaitReleasedFrames() {
  if (!std::exchange(frames_released_, false)) return false;
  devices_.can->AwaitEchoes(t_last_event_, CanEndpoint::kSentFramesWait);
  return true;
}

bool DeviceIo::SendAll() {
  if (!refused_ && !pacer_.SendAll()) refused_ = true;
  return !refused_;
}

}  // namespace hil::harness

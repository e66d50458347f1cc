#include "hil/harness/replay/replay.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/engine/engine.h"
#include "hil/harness/engine/wall_clock_pacer.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/replay/replay_device.h"
#include "hil/harness/run/device_set.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

// What the captures hold, read before any link is opened.
struct ReplayPlan {
  std::vector<ReplayItem> items;
  std::vector<std::pair<std::string, int>> serial;         // link, recorded baud: one port each
  std::string can_iface;                                   // the interface every CAN frame goes to
  std::vector<std::pair<std::string, std::string>> links;  // {name, path} in the captures' order
  UnixTime start_utc{};  // UTC of emulated t = 0: the first capture that knows it (or the epoch)
};

bool LooksLikeCandumpLog(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    return line.front() == '(';
  }
  return false;
}

// The one CAN interface of the replay (--can-iface, else as recorded, else vcan0).
void UseCanInterface(const ReplayOptions& opt, const std::string& recorded, ReplayPlan& plan) {
  const std::string iface = !opt.can_iface.empty() ? opt.can_iface
                            : recorded.empty()     ? "vcan0"
                                                   : recorded;
  if (plan.can_iface == iface) return;
  if (!plan.can_iface.empty()) {
    throw std::runtime_error("the captures name two CAN interfaces (" + plan.can_iface + ", " +
                             iface + "): play them onto one with --can-iface");
  }
  plan.can_iface = iface;
  plan.links.emplace_back(iface, iface);
}

void AddCandumpLog(const ReplayOptions& opt, const std::string& path, ReplayPlan& plan) {
  const link::CandumpLog log = link::ReadCandumpLog(path);
  if (log.records.empty()) throw std::runtime_error(path + " holds no CAN frame");
  const UnixTime t0 = log.records.front().t;
  if (plan.start_utc == UnixTime{}) plan.start_utc = t0;
  for (const auto& r : log.records) {
    UseCanInterface(opt, r.iface, plan);
    ReplayItem item;
    item.t = Time{} + (r.t - t0);
    item.record.dir = CaptureDir::kFrameTx;
    item.record.t_emu_ns = ToNs(item.t);
    item.record.frame = r.frame;
    plan.items.push_back(item);
  }
}

void AddCapture(const ReplayOptions& opt, const std::string& path, const std::string& dir,
                ReplayPlan& plan) {
  const Capture c = ReadCapture(path);
  if (c.header.start_utc && plan.start_utc == UnixTime{}) plan.start_utc = *c.header.start_utc;
  const bool can = c.header.kind == "can";
  if (can) {
    UseCanInterface(opt, c.header.iface, plan);
  } else {
    const std::string link = c.header.link.empty() ? fs::path(path).stem().string() : c.header.link;
    // the bytes keep their recorded times whatever the baud; without one the port is set to 9600
    plan.serial.emplace_back(link, c.header.baud > 0 ? c.header.baud : 9600);
    plan.links.emplace_back(link, link::IsDevicePath(link) ? link : dir + "/" + link);
  }
  const int port = can ? -1 : static_cast<int>(plan.serial.size()) - 1;
  for (const auto& r : c.records) {
    if (can ? r.dir != CaptureDir::kFrameTx : (r.dir != CaptureDir::kTx || r.bytes.empty()))
      continue;
    plan.items.push_back({TimeFromNs(r.t_emu_ns), port, r});
  }
}

// The replay's device set: one ReplayDevice, a serial endpoint per serial capture (a fresh pty,
// or the real device of a /dev link) and the CAN bus, each re-captured in `dir`/captures.
DeviceSet MakeReplaySet(ReplayPlan& plan, const std::string& dir) {
  DeviceSet set;
  if (!plan.can_iface.empty())
    set.can = std::make_unique<CanEndpoint>(plan.can_iface, dir + "/captures", plan.start_utc);
  std::vector<std::unique_ptr<SerialEndpoint>> ports;
  std::vector<int> bauds;
  for (const auto& [link, baud] : plan.serial) {
    ports.push_back(std::make_unique<SerialEndpoint>(link, dir + "/" + link, baud, 4096,
                                                     dir + "/captures/" + CaptureFileName(link)));
    bauds.push_back(baud);
  }
  set.devices.push_back(std::make_unique<ReplayDevice>(std::move(plan.items), std::move(bauds)));
  set.endpoints.push_back(std::move(ports));
  return set;
}

// A replay goes on to its last recorded time: nobody is watched.
class PlayToTheEnd final : public EngineMonitor {
 public:
  bool KeepGoing(Time) override { return true; }
};

// Closing a pty discards what its host has not read yet, including bytes still in the kernel's
// flip buffer (not counted by FIONREAD): waits until every queue has been empty for 50 ms (≤ 2 s).
void WaitUntilRead(const DeviceSet& set) {
  const WallTime drain_deadline = WallNow() + std::chrono::seconds(2);
  for (int quiet_ms = 0; quiet_ms < 50 && WallNow() < drain_deadline; quiet_ms += 2) {
    for (const auto& ep : set.endpoints.front()) {
      if (ep->PendingToHost() > 0) quiet_ms = 0;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

ReplayResult ResultOf(const DeviceSet& set, const link::RealtimePacer& pacer) {
  ReplayResult result;
  result.wall_start = pacer.WallTimeOf(Time{});
  for (const auto& ep : set.endpoints.front())
    result.byte_schedule_error_us.Merge(ep->schedule_error_us());
  result.bytes = result.byte_schedule_error_us.count();
  if (set.can) {
    result.frames = set.can->stats().frames_sent;
    result.frames_failed = set.can->stats().send_failures + set.can->stats().send_queue_full;
    result.frame_schedule_error_us = set.can->schedule_error_us();
  }
  return result;
}

}  // namespace

ReplayResult ReplayCaptures(const ReplayOptions& opt) {
  if (opt.captures.empty())
    throw std::runtime_error("nothing to replay: give at least one capture");
  fs::create_directories(opt.out_dir + "/captures");
  const std::string dir = fs::absolute(opt.out_dir).string();
  ReplayPlan plan;
  for (const std::string& path : opt.captures) {
    if (LooksLikeCandumpLog(path)) {
      AddCandumpLog(opt, path, plan);
    } else {
      AddCapture(opt, path, dir, plan);
    }
  }
  Time t_last{};
  for (const ReplayItem& item : plan.items) t_last = std::max(t_last, item.t);
  DeviceSet set = MakeReplaySet(plan, dir);
  if (opt.on_links) opt.on_links(plan.links);

  link::RealtimePacer::RequestRealtimeScheduling();
  std::this_thread::sleep_for(
      std::chrono::nanoseconds(static_cast<std::int64_t>(opt.start_delay_s * 1e9)));
  WallClockPacer pacer{link::RealtimePacer(opt.speed)};  // emulated t = 0 is now
  Engine engine(EngineDevices{set.devices, set.endpoints, set.can.get(), set.base, set.steering},
                pacer, std::make_unique<NoHostTurns>(), t_last);
  PlayToTheEnd monitor;
  engine.Run(monitor, nullptr);
  engine.Flush();
  WaitUntilRead(set);
  return ResultOf(set, *pacer.wall_clock());
}

}  // namespace hil::harness

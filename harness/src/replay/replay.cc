#include "hil/harness/replay/replay.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/pty_port.h"
#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/firmware_emu/link/socketcan_port.h"
#include "hil/firmware_emu/link/tty_port.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

// One serial link being replayed and re-captured.
struct SerialOut {
  std::string link;
  std::unique_ptr<link::SerialPort> port;
  std::unique_ptr<CaptureWriter> capture;
};

// One CAN interface being replayed and re-captured.
struct CanOut {
  std::unique_ptr<link::SocketCanPort> port;
  std::unique_ptr<link::CandumpLogWriter> candump;
  std::unique_ptr<CaptureWriter> capture;
};

// One thing to play: a serial chunk (bytes back to back) or a CAN frame.
struct Event {
  std::int64_t t_emu_ns = 0;
  int serial = -1;  // index into serial outputs, or
  int can = -1;     // index into CAN outputs
  CaptureRecord record;
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

}  // namespace

ReplayResult ReplayCaptures(const ReplayOptions& opt) {
  if (opt.captures.empty())
    throw std::runtime_error("nothing to replay: give at least one capture");
  fs::create_directories(opt.out_dir + "/captures");
  const std::string dir = fs::absolute(opt.out_dir).string();

  std::vector<SerialOut> serial;
  std::vector<CanOut> can;
  std::map<std::string, int> can_index;
  std::vector<Event> events;
  std::vector<std::pair<std::string, std::string>> links;

  const auto can_out = [&](const std::string& recorded_iface, std::int64_t start_unix_ns) {
    const std::string iface = !opt.can_iface.empty()   ? opt.can_iface
                              : recorded_iface.empty() ? "vcan0"
                                                       : recorded_iface;
    if (auto it = can_index.find(iface); it != can_index.end()) return it->second;
    CanOut o;
    o.port = std::make_unique<link::SocketCanPort>(iface);
    o.candump = std::make_unique<link::CandumpLogWriter>(dir + "/captures/" + iface + ".candump");
    CaptureHeader h;
    h.link = iface;
    h.kind = "can";
    h.iface = iface;
    h.start_unix_ns = start_unix_ns;
    o.capture = std::make_unique<CaptureWriter>(dir + "/captures/" + iface + ".cap", h);
    can.push_back(std::move(o));
    links.emplace_back(iface, iface);
    can_index[iface] = static_cast<int>(can.size()) - 1;
    return static_cast<int>(can.size()) - 1;
  };

  std::int64_t start_unix_ns = 0;
  for (const std::string& path : opt.captures) {
    if (LooksLikeCandumpLog(path)) {
      const link::CandumpLog log = link::ReadCandumpLog(path);
      if (log.records.empty()) throw std::runtime_error(path + " holds no CAN frame");
      const std::int64_t t0 = log.records.front().t_unix_ns;
      if (start_unix_ns == 0) start_unix_ns = t0;
      for (const auto& r : log.records) {
        Event e;
        e.t_emu_ns = r.t_unix_ns - t0;
        e.can = can_out(r.iface, t0);
        e.record.dir = CaptureDir::kFrameTx;
        e.record.t_emu_ns = e.t_emu_ns;
        e.record.frame = r.frame;
        events.push_back(e);
      }
      continue;
    }
    const Capture c = ReadCapture(path);
    if (c.header.start_unix_ns != 0 && start_unix_ns == 0) start_unix_ns = c.header.start_unix_ns;
    if (c.header.kind == "can") {
      for (const auto& r : c.records) {
        if (r.dir != CaptureDir::kFrameTx) continue;
        Event e;
        e.t_emu_ns = r.t_emu_ns;
        e.can = can_out(c.header.iface, c.header.start_unix_ns);
        e.record = r;
        events.push_back(e);
      }
      continue;
    }
    SerialOut o;
    o.link = c.header.link.empty() ? fs::path(path).stem().string() : c.header.link;
    if (link::IsDevicePath(o.link)) {
      o.port = std::make_unique<link::TtyPort>(o.link, c.header.baud);
    } else {
      o.port = std::make_unique<link::PtyPort>(dir + "/" + o.link, c.header.baud);
    }
    CaptureHeader h = c.header;
    h.version = 2;
    h.kind = "serial";
    h.link = o.link;
    o.capture = std::make_unique<CaptureWriter>(dir + "/captures/" + CaptureFileName(o.link), h);
    links.emplace_back(o.link, o.port->path());
    serial.push_back(std::move(o));
    for (const auto& r : c.records) {
      if (r.dir != CaptureDir::kTx || r.bytes.empty()) continue;
      Event e;
      e.t_emu_ns = r.t_emu_ns;
      e.serial = static_cast<int>(serial.size()) - 1;
      e.record = r;
      events.push_back(e);
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.t_emu_ns < b.t_emu_ns; });
  if (opt.on_links) opt.on_links(links);

  link::RealtimePacer::RequestRealtimeScheduling();
  std::this_thread::sleep_for(
      std::chrono::nanoseconds(static_cast<std::int64_t>(opt.start_delay_s * 1e9)));
  const link::RealtimePacer pacer(opt.speed);
  ReplayResult result;
  result.wall_start_ns = pacer.WallNsOf(Time{});

  // serial chunks are played byte by byte, interleaved in time with every other event
  struct Cursor {
    std::size_t event;
    std::size_t byte;
    CaptureRecord out;
  };
  std::vector<Cursor> active;  // serial chunks in progress
  std::size_t next = 0;
  for (;;) {
    // earliest of: the next new event, the next byte of an active chunk
    std::optional<std::int64_t> t_next;
    int pick = -1;
    for (std::size_t i = 0; i < active.size(); ++i) {
      const auto& ev = events[active[i].event].record;
      const std::int64_t t = ToNs(ev.t_byte(active[i].byte));
      if (!t_next || t < *t_next) {
        t_next = t;
        pick = static_cast<int>(i);
      }
    }
    if (next < events.size() && (!t_next || events[next].t_emu_ns <= *t_next)) {
      Event& e = events[next++];
      if (e.serial >= 0) {
        Cursor cur{next - 1, 0, e.record};
        cur.out.t_wall_ns = 0;
        cur.out.wall_offsets_ns.clear();
        active.push_back(std::move(cur));
        continue;
      }
      CanOut& o = can[static_cast<std::size_t>(e.can)];
      const Time t = TimeFromNs(e.t_emu_ns);
      const std::int64_t scheduled = pacer.WallNsOf(t);
      pacer.SleepUntil(t);
      const auto sent = o.port->Send(e.record.frame);
      if (sent) {
        ++result.frames;
        result.frame_schedule_error_us.push_back(static_cast<double>(*sent - scheduled) * 1e-3);
      } else {
        ++result.frames_failed;
      }
      CaptureRecord r = e.record;
      r.t_wall_ns = sent.value_or(0);
      r.name = o.port->ifname();
      r.wall_offsets_ns.clear();
      o.capture->Write(r);
      link::CandumpRecord lr;
      lr.t_unix_ns = start_unix_ns + e.t_emu_ns;
      lr.iface = o.port->ifname();
      lr.frame = e.record.frame;
      o.candump->Write(lr);
      continue;
    }
    if (pick < 0) break;
    Cursor& cur = active[static_cast<std::size_t>(pick)];
    const Event& e = events[cur.event];
    SerialOut& o = serial[static_cast<std::size_t>(e.serial)];
    const Time t = e.record.t_byte(cur.byte);
    const std::int64_t scheduled = pacer.WallNsOf(t);
    pacer.SleepUntil(t);
    o.port->Write(std::string_view(e.record.bytes).substr(cur.byte, 1));
    const std::int64_t wall = link::RealtimePacer::MonotonicNs();
    result.byte_schedule_error_us.push_back(static_cast<double>(wall - scheduled) * 1e-3);
    ++result.bytes;
    if (cur.byte == 0) cur.out.t_wall_ns = wall;
    cur.out.wall_offsets_ns.push_back(wall - cur.out.t_wall_ns);
    if (++cur.byte == e.record.bytes.size()) {
      o.capture->Write(cur.out);
      active.erase(active.begin() + pick);
    }
  }
  // closing a pty discards what its host has not read yet, including bytes still in the kernel's
  // flip buffer (not counted by FIONREAD): wait until every queue has been empty for 50 ms (≤ 2 s)
  const std::int64_t drain_deadline = link::RealtimePacer::MonotonicNs() + 2000000000LL;
  for (int quiet_ms = 0; quiet_ms < 50 && link::RealtimePacer::MonotonicNs() < drain_deadline;
       quiet_ms += 2) {
    for (const SerialOut& o : serial) {
      if (o.port->PendingToHost() > 0) quiet_ms = 0;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return result;
}

}  // namespace hil::harness

#include "hil/harness/validate/validate_can_live.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/socketcan_port.h"
#include "hil/firmware_emu/wall_time.h"

namespace hil::harness {

bool IsNetworkInterface(const std::string& source) {
  std::error_code ec;
  if (source.empty() || source.find('/') != std::string::npos ||
      std::filesystem::exists(source, ec))
    return false;
  return std::filesystem::exists("/sys/class/net/" + source, ec);
}

CanListen ListenCanInterface(const std::string& iface, double listen_s) {
  if (!link::SocketCanPort::Available()) {
    throw std::runtime_error(
        "cannot listen to " + iface +
        ": this kernel has no SocketCAN (AF_CAN); use the vcan VM (ci/vcan/run_in_vm)");
  }
  link::SocketCanPort port(iface, link::SocketCanPort::Options{});
  CanListen out;
  const WallTime end = WallNow() + DurationFromSeconds(listen_s);
  for (WallTime now = WallNow(); now < end; now = WallNow()) {
    const auto r = port.Receive(std::min<Duration>(end - now, std::chrono::milliseconds(100)));
    if (!r) continue;
    link::CandumpRecord rec;
    rec.t = r->t_kernel;
    rec.iface = iface;
    rec.frame = r->frame;
    out.candump_text += link::FormatCandumpLine(rec) + "\n";
  }
  out.frames = port.stats().frames_received;
  out.rx_queue_drops = port.stats().rx_queue_drops;
  out.error_frames = port.stats().error_frames;
  return out;
}

ValidationReport ValidateCanInterface(const std::string& iface, double listen_s) {
  const CanListen l = ListenCanInterface(iface, listen_s);
  ValidationReport rep = ValidateCanLog(l.candump_text);
  char what[160];
  std::snprintf(what, sizeof what, "live CAN interface %s, listened to for %g s (%llu frames)",
                iface.c_str(), listen_s, static_cast<unsigned long long>(l.frames));
  rep.description = what;
  if (l.rx_queue_drops > 0) {
    rep.findings.push_back({true, "overflow",
                            std::to_string(l.rx_queue_drops) +
                                " frame(s) dropped by the receive queue while listening",
                            -1});
  }
  return rep;
}

}  // namespace hil::harness

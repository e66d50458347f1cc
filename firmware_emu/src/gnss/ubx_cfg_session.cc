#include "hil/firmware_emu/gnss/ubx_cfg_session.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss::ubx {
namespace {

enum CfgId : std::uint8_t {
  kPrt = 0x00,
  kMsg = 0x01,
  kRst = 0x04,
  kTp = 0x07,
  kRate = 0x08,
  kCfgCfg = 0x09,
  kSbas = 0x16,
  kNmea = 0x17,
  kNav5 = 0x24
};

constexpr std::uint16_t Key(std::uint8_t cls, std::uint8_t id) {
  return static_cast<std::uint16_t>((cls << 8) | id);
}

// NMEA message ids in class 0xF0, by sentence name (for $PUBX,40).
constexpr std::pair<const char*, std::uint8_t> kNmeaIds[] = {
    {"GGA", 0x00}, {"GLL", 0x01}, {"GSA", 0x02}, {"GSV", 0x03}, {"RMC", 0x04},
    {"VTG", 0x05}, {"GRS", 0x06}, {"GST", 0x07}, {"ZDA", 0x08}};

std::vector<std::string> SplitFields(const std::string& body) {
  std::vector<std::string> f;
  std::stringstream ss(body);
  std::string item;
  while (std::getline(ss, item, ',')) f.push_back(item);
  if (!body.empty() && body.back() == ',') f.emplace_back();
  return f;
}

bool ParseUint(const std::string& s, int base, unsigned long& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtoul(s.c_str(), &end, base);
  return end != nullptr && *end == '\0';
}

}  // namespace

bool IsSupportedBaud(std::uint32_t baud) {
  static constexpr std::uint32_t kBauds[] = {4800, 9600, 19200, 38400, 57600, 115200, 230400};
  return std::find(std::begin(kBauds), std::end(kBauds), baud) != std::end(kBauds);
}

int ReceiverSettings::Rate(std::uint8_t cls, std::uint8_t id) const {
  const auto it = rates.find(Key(cls, id));
  return it == rates.end() ? 0 : it->second[kUart1];
}

void ReceiverSettings::SetRate(std::uint8_t cls, std::uint8_t id, int target, std::uint8_t rate) {
  rates[Key(cls, id)][static_cast<std::size_t>(target)] = rate;
}

FixMode ReceiverSettings::fix_mode() const {
  return nav5[3] == 1 ? FixMode::k2DOnly : nav5[3] == 2 ? FixMode::k3DOnly : FixMode::kAuto;
}

double ReceiverSettings::min_elevation_deg() const { return static_cast<std::int8_t>(nav5[12]); }

ReceiverSettings ReceiverSettings::Defaults(
    std::uint32_t baud, std::uint16_t meas_rate_ms,
    const std::map<std::uint8_t, std::uint8_t>& nmea_rates) {
  ReceiverSettings s;
  s.ports[kUart1].baud = baud;
  s.ports[2].baud = 9600;
  s.meas_rate_ms = meas_rate_ms;
  for (const auto& [id, rate] : nmea_rates) {
    for (int p = 0; p < kNumPorts; ++p) s.SetRate(kNmeaStd, id, p, rate);
  }
  // CFG-NAV5: the u-blox 5 frame quoted in the fact sheet (portable, auto 2D/3D, minElev 5°,
  // PDOP/TDOP masks 25.0, pAcc 100 m, tAcc 300 m), with the all-ones mask a poll reports
  const std::array<std::uint8_t, 36> nav5{0xFF, 0xFF, 0x00, 0x03, 0,    0,    0,    0,
                                          0x10, 0x27, 0,    0,    0x05, 0x00, 0xFA, 0x00,
                                          0xFA, 0x00, 0x64, 0x00, 0x2C, 0x01, 0x00};
  s.nav5 = nav5;
  s.sbas = {0x01, 0x03, 0x03, 0x00,
            0,    0,    0,    0};  // enabled, range + corrections, up to 3 SBAS, auto-scan
  // CFG-TP: 1 s interval, 100 ms pulse, rising, UTC, 50 ns cable delay (UNVERIFIED u-blox 5
  // defaults)
  Writer tp;
  tp.U4(1000000).U4(100000).I1(1).U1(0).U1(0).U1(0).I2(50).I2(0).I4(0);
  std::copy(tp.bytes().begin(), tp.bytes().end(), s.tp.begin());
  s.nmea = {0x00, 0x23, 0x00, 0x02};  // no filters, NMEA 2.3, unlimited SVs, consider mode
  return s;
}

UbxCfgSession::UbxCfgSession(const ReceiverSettings& defaults, double max_rate_hz)
    : defaults_(defaults), current_(defaults), saved_(defaults), max_rate_hz_(max_rate_hz) {}

bool UbxCfgSession::Known(std::uint8_t cls, std::uint8_t id) const {
  switch (cls) {
    case kNav:
      return std::find(std::begin(kNavOutputOrder), std::end(kNavOutputOrder), id) !=
             std::end(kNavOutputOrder);
    case kRxm:
      return id == 0x10 || id == 0x11 ||
             id == 0x20;  // RAW, SFRB, SVSI: accepted, never output by a NEO-5M
    case kMon:
      return id == kMonHw || id == 0x02 || id == 0x06 || id == 0x07 || id == 0x08;
    case kTim:
      return id == 0x01 || id == 0x03;  // TIM-TP, TIM-TM2
    case kNmeaStd:
      return id <= 0x08;
    case kNmeaPubx:
      return id == 0x00 || id == 0x03 || id == 0x04;
    default:
      return false;
  }
}

std::vector<std::uint8_t> UbxCfgSession::PortBlock(int port_id) const {
  const PortSettings& p = current_.ports[static_cast<std::size_t>(port_id)];
  Writer w;
  w.U1(static_cast<std::uint64_t>(port_id)).U1(0).U2(0);
  const bool uart = port_id == 1 || port_id == 2;
  w.U4(uart ? p.mode : 0).U4(uart ? p.baud : 0).U2(p.in_mask).U2(p.out_mask).U2(0).U2(0);
  return w.bytes();
}

void UbxCfgSession::CopySections(const ReceiverSettings& from, ReceiverSettings& to,
                                 std::uint32_t mask) const {
  if (mask & 0x01) to.ports = from.ports;
  if (mask & 0x02) to.rates = from.rates;
  if (mask & 0x08) {
    to.meas_rate_ms = from.meas_rate_ms;
    to.nav_rate = from.nav_rate;
    to.time_ref = from.time_ref;
    to.nav5 = from.nav5;
    to.sbas = from.sbas;
    to.tp = from.tp;
    to.nmea = from.nmea;
  }
}

// The replies to one CFG message, in order: polled messages and the ACK-ACK or ACK-NAK.
class CfgReplies {
 public:
  explicit CfgReplies(std::uint8_t id) : id_(id) {}
  void Message(const std::vector<std::uint8_t>& p) {
    out_.push_back({Frame(kCfg, id_, p), MessageName(kCfg, id_)});
  }
  void Acknowledge(bool ok) {
    out_.push_back({Ack(ok, kCfg, id_), ok ? "UBX-ACK-ACK" : "UBX-ACK-NAK"});
  }
  template <typename Array>
  void PollArray(const Array& arr) {
    Message(std::vector<std::uint8_t>(arr.begin(), arr.end()));
    Acknowledge(true);
  }
  std::vector<Reply> Take() { return std::move(out_); }

 private:
  std::uint8_t id_;
  std::vector<Reply> out_;
};

namespace {

// A fixed-size CFG payload the receiver keeps as it arrived: polled with an empty payload, set with
// one of its size when `valid`.
template <std::size_t N>
void PollOrSet(std::array<std::uint8_t, N>& kept, const std::vector<std::uint8_t>& payload,
               bool valid, CfgReplies& out) {
  if (payload.empty()) return out.PollArray(kept);
  if (payload.size() != N || !valid) return out.Acknowledge(false);
  std::copy(payload.begin(), payload.end(), kept.begin());
  out.Acknowledge(true);
}

}  // namespace

void UbxCfgSession::HandlePrt(const std::vector<std::uint8_t>& payload, int port_id,
                              CfgReplies& out) {
  const Reader r(payload);
  const std::size_t n = payload.size();
  if (n == 0 || n == 1) {
    const int pid = n == 0 ? port_id : r.U1(0);
    if (pid >= kNumPorts) return out.Acknowledge(false);
    out.Message(PortBlock(pid));
    return out.Acknowledge(true);
  }
  if (n % 20 != 0) return out.Acknowledge(false);
  for (std::size_t off = 0; off < n; off += 20) {
    const int pid = r.U1(off);
    const bool uart = pid == 1 || pid == 2;
    if (pid >= kNumPorts || (uart && !IsSupportedBaud(r.U4(off + 8)))) {
      return out.Acknowledge(false);
    }
  }
  for (std::size_t off = 0; off < n; off += 20) {
    PortSettings& p = current_.ports[r.U1(off)];
    if (r.U1(off) == 1 || r.U1(off) == 2) {
      p.mode = r.U4(off + 4);
      p.baud = r.U4(off + 8);
    }
    p.in_mask = r.U2(off + 12) & 0x07;
    p.out_mask = r.U2(off + 14) & 0x03;  // RTCM output does not exist on u-blox 5
  }
  out.Acknowledge(true);
}

void UbxCfgSession::HandleMsg(const std::vector<std::uint8_t>& payload, int port_id,
                              CfgReplies& out) {
  const Reader r(payload);
  const std::size_t n = payload.size();
  if (n < 2 || (n != 2 && n != 3 && n != 8)) return out.Acknowledge(false);
  const std::uint8_t cls = r.U1(0), mid = r.U1(1);
  if (!Known(cls, mid)) return out.Acknowledge(false);
  if (n == 2) {
    Writer w;
    w.U1(cls).U1(mid);
    const auto it = current_.rates.find(Key(cls, mid));
    for (std::size_t k = 0; k < 6; ++k) w.U1(it == current_.rates.end() ? 0 : it->second[k]);
    out.Message(w.bytes());
    return out.Acknowledge(true);
  }
  if (n == 3)
    current_.SetRate(cls, mid, port_id, r.U1(2));
  else
    for (int k = 0; k < 6; ++k)
      current_.SetRate(cls, mid, k, r.U1(2 + static_cast<std::size_t>(k)));
  out.Acknowledge(true);
}

void UbxCfgSession::HandleRate(const std::vector<std::uint8_t>& payload, CfgReplies& out) {
  const Reader r(payload);
  const std::size_t n = payload.size();
  if (n == 0) {
    Writer w;
    w.U2(current_.meas_rate_ms).U2(current_.nav_rate).U2(current_.time_ref);
    out.Message(w.bytes());
    return out.Acknowledge(true);
  }
  const std::uint16_t meas = r.U2(0), nav = r.U2(2), tref = r.U2(4);
  const double min_period_ms = 1000.0 / max_rate_hz_ - 1e-9;
  if (n != 6 || nav != 1 || tref > 1 || meas < min_period_ms) return out.Acknowledge(false);
  current_.meas_rate_ms = meas;
  current_.time_ref = tref;
  out.Acknowledge(true);
}

void UbxCfgSession::HandleNav5(const std::vector<std::uint8_t>& payload, CfgReplies& out) {
  const Reader r(payload);
  const std::size_t n = payload.size();
  if (n == 0) return out.PollArray(current_.nav5);
  if (n != 36) return out.Acknowledge(false);
  const std::uint16_t mask = r.U2(0);
  const std::uint8_t dyn = r.U1(2), fix_mode = r.U1(3);
  if ((mask & 0x01) && (dyn == 1 || dyn > 8)) return out.Acknowledge(false);
  if ((mask & 0x04) && (fix_mode < 1 || fix_mode > 3)) return out.Acknowledge(false);
  auto& s = current_.nav5;
  const auto copy = [&](std::size_t from, std::size_t len) {
    for (std::size_t k = from; k < from + len; ++k) s[k] = payload[k];
  };
  if (mask & 0x01) copy(2, 1);
  if (mask & 0x02) copy(12, 1);
  if (mask & 0x04) copy(3, 9);
  if (mask & 0x08) copy(13, 1);
  if (mask & 0x10) copy(14, 2), copy(18, 2);
  if (mask & 0x20) copy(16, 2), copy(20, 2);
  if (mask & 0x40) copy(22, 1);
  out.Acknowledge(true);
}

void UbxCfgSession::HandleRst(const std::vector<std::uint8_t>& payload, CfgReplies& out,
                              CfgEffects& fx) {
  const Reader r(payload);
  if (payload.size() != 4) return out.Acknowledge(false);
  const std::uint16_t bbr = r.U2(0);
  const std::uint8_t mode = r.U1(2);
  if (mode != 0 && mode != 1 && mode != 2 && mode != 4 && mode != 8 && mode != 9)
    return out.Acknowledge(false);
  // u-blox 5 firmware acknowledges before resetting (later firmware does not)
  out.Acknowledge(true);
  if (mode == 8) {
    fx.gps_stop = true;
    return;
  }
  if (mode == 9) {
    fx.gps_start = true;
    return;
  }
  // navBbrMask: nothing cleared = hot, everything = cold, anything else (ephemeris …) = warm
  fx.restart = bbr == 0x0000   ? StartKind::kHot
               : bbr == 0xFFFF ? StartKind::kCold
                               : StartKind::kWarm;
  fx.hardware_reset = mode != 2;
}

std::vector<Reply> UbxCfgSession::Handle(std::uint8_t id, const std::vector<std::uint8_t>& payload,
                                         int port_id, CfgEffects& fx) {
  CfgReplies out(id);
  const Reader r(payload);
  const std::size_t n = payload.size();
  switch (id) {
    case kPrt:
      HandlePrt(payload, port_id, out);
      break;
    case kMsg:
      HandleMsg(payload, port_id, out);
      break;
    case kRate:
      HandleRate(payload, out);
      break;
    case kNav5:
      HandleNav5(payload, out);
      break;
    case kSbas:
      PollOrSet(current_.sbas, payload, r.U1(2) <= 3, out);
      break;
    case kTp: {
      const int status = r.I1(8);
      PollOrSet(current_.tp, payload,
                status >= -1 && status <= 1 && r.U1(9) <= 2 && r.U4(4) <= r.U4(0), out);
      break;
    }
    case kNmea:
      PollOrSet(current_.nmea, payload, r.U1(1) == 0x23 || r.U1(1) == 0x21, out);
      break;
    case kCfgCfg:
      if (n != 12 && n != 13) {
        out.Acknowledge(false);
        break;
      }
      CopySections(defaults_, current_, r.U4(0));  // clear
      CopySections(current_, saved_, r.U4(4));     // save
      CopySections(saved_, current_, r.U4(8));     // load
      out.Acknowledge(true);
      break;
    case kRst:
      HandleRst(payload, out, fx);
      break;
    default:
      out.Acknowledge(false);  // a CFG message this receiver does not have
      break;
  }
  return out.Take();
}

bool UbxCfgSession::HandlePubxSet(const std::string& body) {
  const std::vector<std::string> f = SplitFields(body);
  if (f.size() < 2 || f[0] != "PUBX") return false;
  if (f[1] == "40") {
    if (f.size() < 8) return false;
    std::optional<std::uint8_t> mid;
    for (const auto& [name, id] : kNmeaIds) {
      if (f[2] == name) mid = id;
    }
    if (!mid) return false;
    std::array<std::uint8_t, 6> rates{};
    for (std::size_t k = 0; k < 6; ++k) {
      unsigned long v = 0;
      if (k + 3 < f.size() && !f[k + 3].empty()) {
        if (!ParseUint(f[k + 3], 10, v) || v > 255) return false;
      }
      rates[k] = static_cast<std::uint8_t>(v);
    }
    for (int k = 0; k < 6; ++k)
      current_.SetRate(kNmeaStd, *mid, k, rates[static_cast<std::size_t>(k)]);
    return true;
  }
  if (f[1] == "41") {
    unsigned long port = 0, in = 0, out = 0, baud = 0;
    if (f.size() < 7 || !ParseUint(f[2], 10, port) || !ParseUint(f[3], 16, in) ||
        !ParseUint(f[4], 16, out) || !ParseUint(f[5], 10, baud)) {
      return false;
    }
    if (port >= kNumPorts ||
        ((port == 1 || port == 2) && !IsSupportedBaud(static_cast<std::uint32_t>(baud))))
      return false;
    PortSettings& p = current_.ports[port];
    p.in_mask = static_cast<std::uint16_t>(in & 0x07);
    p.out_mask = static_cast<std::uint16_t>(out & 0x03);
    if (port == 1 || port == 2) p.baud = static_cast<std::uint32_t>(baud);
    return true;
  }
  return false;
}

}  // namespace hil::gnss::ubx

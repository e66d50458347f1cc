#include "hil/firmware_emu/gnss/ubx_f9_config.h"

#include <algorithm>

#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss::ubx {
namespace {

// Defaults of the ZED-F9P interface description (HPG 1.32), as vectors/gnss/README.md lists them.
constexpr F9Key kKeys[] = {
    {f9key::kUart1InUbx, "CFG-UART1INPROT-UBX", 1},
    {f9key::kUart1InNmea, "CFG-UART1INPROT-NMEA", 1},
    {f9key::kUart1InRtcm3, "CFG-UART1INPROT-RTCM3X", 1},
    {f9key::kUart1OutUbx, "CFG-UART1OUTPROT-UBX", 1},
    {f9key::kUart1OutNmea, "CFG-UART1OUTPROT-NMEA", 1},
    {f9key::kUart1OutRtcm3, "CFG-UART1OUTPROT-RTCM3X", 1},
    {f9key::kUart2InUbx, "CFG-UART2INPROT-UBX", 1},
    {f9key::kUart2InNmea, "CFG-UART2INPROT-NMEA", 0},
    {f9key::kUart2InRtcm3, "CFG-UART2INPROT-RTCM3X", 1},
    {f9key::kNavhpgDgnssMode, "CFG-NAVHPG-DGNSSMODE", 3},
    {f9key::kNavspgDynModel, "CFG-NAVSPG-DYNMODEL", 0},
    {f9key::kNavspgConstrDgnssTo, "CFG-NAVSPG-CONSTR_DGNSSTO", 60},
    {f9key::kNavPvtUart1, "CFG-MSGOUT-UBX_NAV_PVT_UART1", 0},
    {f9key::kNavSatUart1, "CFG-MSGOUT-UBX_NAV_SAT_UART1", 0},
    {f9key::kNavHpposllhUart1, "CFG-MSGOUT-UBX_NAV_HPPOSLLH_UART1", 0},
    {f9key::kNavRelposnedUart1, "CFG-MSGOUT-UBX_NAV_RELPOSNED_UART1", 0},
    {f9key::kNmeaRmcUart1, "CFG-MSGOUT-NMEA_ID_RMC_UART1", 1},
    {f9key::kNmeaVtgUart1, "CFG-MSGOUT-NMEA_ID_VTG_UART1", 1},
    {f9key::kNmeaGgaUart1, "CFG-MSGOUT-NMEA_ID_GGA_UART1", 1},
    {f9key::kNmeaGsaUart1, "CFG-MSGOUT-NMEA_ID_GSA_UART1", 1},
    {f9key::kNmeaGsvUart1, "CFG-MSGOUT-NMEA_ID_GSV_UART1", 1},
    {f9key::kNmeaGllUart1, "CFG-MSGOUT-NMEA_ID_GLL_UART1", 1},
    {f9key::kRxmRtcmUart1, "CFG-MSGOUT-UBX_RXM_RTCM_UART1", 0},
    {f9key::kRxmRawxUart1, "CFG-MSGOUT-UBX_RXM_RAWX_UART1", 0},
    {f9key::kRateMeas, "CFG-RATE-MEAS", 1000},
    {f9key::kRateNav, "CFG-RATE-NAV", 1},
    {f9key::kUart1Baudrate, "CFG-UART1-BAUDRATE", 38400},
    {f9key::kUart2Baudrate, "CFG-UART2-BAUDRATE", 38400},
};

constexpr std::uint32_t kMinMeasPeriod_ms = 25;  // ours (see the header)

std::uint64_t ReadLe(const std::vector<std::uint8_t>& p, std::size_t off, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < n; ++k) v |= static_cast<std::uint64_t>(p[off + k]) << (8 * k);
  return v;
}

void WriteLe(std::vector<std::uint8_t>& p, std::uint64_t v, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) p.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

// The key/value pairs of a cfgData block from `off`; nullopt when a key is unknown, its size
// reserved, a value cut, or a value out of range.
std::optional<std::map<std::uint32_t, std::uint64_t>> ParseCfgData(
    const std::vector<std::uint8_t>& p, std::size_t off) {
  std::map<std::uint32_t, std::uint64_t> values;
  while (off < p.size()) {
    if (off + 4 > p.size()) return std::nullopt;
    const auto id = static_cast<std::uint32_t>(ReadLe(p, off, 4));
    const std::size_t n = F9ValueBytes(id);
    if (FindF9Key(id) == nullptr || n == 0 || off + 4 + n > p.size()) return std::nullopt;
    std::uint64_t v = ReadLe(p, off + 4, n);
    if ((id >> 28 & 7U) == 1) v &= 1U;
    if (id == f9key::kRateMeas && v < kMinMeasPeriod_ms) return std::nullopt;
    if ((id == f9key::kUart1Baudrate || id == f9key::kUart2Baudrate) && v == 0) return std::nullopt;
    values[id] = v;
    off += 4 + n;
  }
  return values;
}

}  // namespace

std::span<const F9Key> F9Keys() { return kKeys; }

const F9Key* FindF9Key(std::uint32_t id) {
  const auto* it =
      std::find_if(std::begin(kKeys), std::end(kKeys), [id](const F9Key& k) { return k.id == id; });
  return it == std::end(kKeys) ? nullptr : it;
}

const F9Key* FindF9Key(std::string_view name) {
  const auto* it = std::find_if(std::begin(kKeys), std::end(kKeys),
                                [name](const F9Key& k) { return k.name == name; });
  return it == std::end(kKeys) ? nullptr : it;
}

std::size_t F9ValueBytes(std::uint32_t id) {
  switch (id >> 28 & 7U) {
    case 1:
    case 2:
      return 1;
    case 3:
      return 2;
    case 4:
      return 4;
    case 5:
      return 8;
    default:
      return 0;
  }
}

std::uint64_t F9ConfigDb::Get(std::uint32_t id) const {
  if (const auto it = ram_.find(id); it != ram_.end()) return it->second;
  const F9Key* k = FindF9Key(id);
  return k != nullptr ? k->default_value : 0;
}

void F9ConfigDb::LoadStored() {
  ram_ = flash_;
  for (const auto& [id, v] : bbr_) ram_[id] = v;
  staged_.reset();
}

void F9ConfigDb::Apply(std::uint8_t layers, const Values& values) {
  for (const auto& [id, v] : values) {
    if ((layers & 1U) != 0) ram_[id] = v;
    if ((layers & 2U) != 0) bbr_[id] = v;
    if ((layers & 4U) != 0) flash_[id] = v;
  }
}

bool F9ConfigDb::ValSet(const std::vector<std::uint8_t>& p) {
  if (p.size() < 4 || p[0] > 1 || (p[1] & 7U) == 0) return false;
  const std::uint8_t transaction = p[0] == 1 ? (p[2] & 3U) : 0;
  const auto values = ParseCfgData(p, 4);
  if (!values || (transaction >= 2 && !staged_)) {
    staged_.reset();  // a rejected message ends the transaction: nothing of it applies
    return false;
  }
  if (transaction == 0) {
    Apply(p[1], *values);
    return true;
  }
  if (transaction == 1) {
    staged_ = Values{};
    staged_layers_ = p[1];
  }
  for (const auto& [id, v] : *values) (*staged_)[id] = v;
  if (transaction == 3) {
    Apply(staged_layers_, *staged_);
    staged_.reset();
  }
  return true;
}

std::optional<std::vector<std::uint8_t>> F9ConfigDb::ValGet(
    const std::vector<std::uint8_t>& p) const {
  if (p.size() < 8 || p[0] != 0 || (p.size() - 4) % 4 != 0) return std::nullopt;
  const std::uint8_t layer = p[1];
  const Values* stored = layer == kLayerBbr ? &bbr_ : layer == kLayerFlash ? &flash_ : nullptr;
  if (layer != kLayerRam && layer != kLayerDefault && stored == nullptr) return std::nullopt;
  std::vector<std::uint8_t> out{1, layer, p[2], p[3]};
  for (std::size_t off = 4; off < p.size(); off += 4) {
    const auto id = static_cast<std::uint32_t>(ReadLe(p, off, 4));
    const F9Key* k = FindF9Key(id);
    if (k == nullptr) return std::nullopt;
    std::uint64_t v = layer == kLayerDefault ? k->default_value : Get(id);
    if (stored != nullptr) {
      const auto it = stored->find(id);
      if (it == stored->end()) continue;
      v = it->second;
    }
    WriteLe(out, id, 4);
    WriteLe(out, v, F9ValueBytes(id));
  }
  if (out.size() == 4) return std::nullopt;
  return out;
}

bool F9ConfigDb::ValDel(const std::vector<std::uint8_t>& p) {
  if (p.size() < 8 || p[0] > 1 || (p[1] & 6U) == 0 || (p.size() - 4) % 4 != 0) return false;
  std::vector<std::uint32_t> ids;
  for (std::size_t off = 4; off < p.size(); off += 4) {
    const auto id = static_cast<std::uint32_t>(ReadLe(p, off, 4));
    if (FindF9Key(id) == nullptr) return false;
    ids.push_back(id);
  }
  for (const std::uint32_t id : ids) {
    if ((p[1] & 2U) != 0) bbr_.erase(id);
    if ((p[1] & 4U) != 0) flash_.erase(id);
  }
  return true;
}

std::vector<Reply> F9ConfigDb::Handle(std::uint8_t id, const std::vector<std::uint8_t>& payload) {
  std::vector<Reply> replies;
  bool ok = false;
  if (id == kCfgValset) {
    ok = ValSet(payload);
  } else if (id == kCfgValdel) {
    ok = ValDel(payload);
  } else if (id == kCfgValget) {
    if (const auto answer = ValGet(payload)) {
      replies.push_back({Frame(kCfg, kCfgValget, *answer), "UBX-CFG-VALGET"});
      ok = true;
    }
  }
  replies.push_back({Ack(ok, kCfg, id), ok ? "UBX-ACK-ACK" : "UBX-ACK-NAK"});
  return replies;
}

}  // namespace hil::gnss::ubx

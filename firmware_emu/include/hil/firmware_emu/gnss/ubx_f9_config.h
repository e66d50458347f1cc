#pragma once
/// @file
/// The configuration database of a u-blox F9 receiver (protocol 27+) and its three messages
/// CFG-VALSET, CFG-VALGET and CFG-VALDEL, as the ZED-F9P interface description (u-blox
/// UBX-18010854, HPG 1.32) describes them. Key IDs, sizes and defaults: vectors/gnss/README.md
/// ("ZED-F9P configuration keys"). Only the keys of that table exist here: any other key makes
/// the whole message NAKed and nothing of it applied, as the receiver rejects a VALSET
/// transaction with an unknown key.
///
/// Layers: RAM (what runs), BBR and Flash (what a reset loads; only the keys stored there),
/// Default (the table). VALSET writes the layers of its `layers` bits; version 1 with a
/// transaction (1 begin, 2 continue, 3 end) stages the keys and applies them all at the end, or
/// none when one message of the transaction is rejected. VALGET reads one layer (0 RAM, 1 BBR,
/// 2 Flash, 7 Default) and answers version 1 with key/value pairs; a key absent from BBR/Flash is
/// left out of the answer, a NAK when none remains. VALDEL removes keys from BBR and/or Flash.
/// Values are not range-checked, except CFG-RATE-MEAS below 25 ms and CFG-UART1-BAUDRATE of 0
/// (NAKed; our choice, the description gives no receiver behaviour for them).

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/gnss/ubx_cfg_session.h"

namespace hil::gnss::ubx {

inline constexpr std::uint8_t kCfgValset = 0x8A, kCfgValget = 0x8B, kCfgValdel = 0x8C;

/// The key IDs the emulated F9 knows (interface description §6.9; vectors/gnss/README.md).
namespace f9key {
inline constexpr std::uint32_t kRateMeas = 0x30210001, kRateNav = 0x30210002;
inline constexpr std::uint32_t kUart1Baudrate = 0x40520001;
inline constexpr std::uint32_t kUart1InUbx = 0x10730001, kUart1InNmea = 0x10730002,
                               kUart1InRtcm3 = 0x10730004;
inline constexpr std::uint32_t kUart1OutUbx = 0x10740001, kUart1OutNmea = 0x10740002,
                               kUart1OutRtcm3 = 0x10740004;
inline constexpr std::uint32_t kUart2Baudrate = 0x40530001;
inline constexpr std::uint32_t kUart2InUbx = 0x10750001, kUart2InNmea = 0x10750002,
                               kUart2InRtcm3 = 0x10750004;
inline constexpr std::uint32_t kNavPvtUart1 = 0x20910007, kNavHpposllhUart1 = 0x20910034,
                               kNavSatUart1 = 0x20910016, kNavRelposnedUart1 = 0x2091008e,
                               kRxmRtcmUart1 = 0x20910269, kRxmRawxUart1 = 0x209102a5;
inline constexpr std::uint32_t kNmeaGgaUart1 = 0x209100bb, kNmeaGllUart1 = 0x209100ca,
                               kNmeaGsaUart1 = 0x209100c0, kNmeaGsvUart1 = 0x209100c5,
                               kNmeaRmcUart1 = 0x209100ac, kNmeaVtgUart1 = 0x209100b1;
inline constexpr std::uint32_t kNavhpgDgnssMode = 0x20140011;
inline constexpr std::uint32_t kNavspgConstrDgnssTo = 0x201100c4;
inline constexpr std::uint32_t kNavspgDynModel = 0x20110021;
}  // namespace f9key

/// One key of the table: its ID, name and default value.
struct F9Key {
  std::uint32_t id;
  std::string_view name;
  std::uint64_t default_value;
};
/// The table, by ID.
std::span<const F9Key> F9Keys();
/// The key `id` of the table, null for an unknown key.
const F9Key* FindF9Key(std::uint32_t id);
/// The key named `name` ("CFG-RATE-MEAS"), null for an unknown name.
const F9Key* FindF9Key(std::string_view name);
/// Bytes of a key's value on the wire: its size field (bits 28–30) 1 (one bit, sent as a byte)
/// and 2 → 1, 3 → 2, 4 → 4, 5 → 8; 0 for a reserved size.
std::size_t F9ValueBytes(std::uint32_t id);

enum F9Layer : std::uint8_t { kLayerRam = 0, kLayerBbr = 1, kLayerFlash = 2, kLayerDefault = 7 };

class F9ConfigDb {
 public:
  /// The value of `id` in RAM (what the receiver runs with); 0 for an unknown key.
  std::uint64_t Get(std::uint32_t id) const;
  /// Handles CFG-VALSET/VALGET/VALDEL (`id` 0x8A/0x8B/0x8C): the replies in order (VALGET's
  /// answer, then ACK-ACK; or ACK-NAK alone).
  std::vector<Reply> Handle(std::uint8_t id, const std::vector<std::uint8_t>& payload);
  /// A reset: RAM becomes the defaults overlaid with Flash, then BBR.
  void LoadStored();

 private:
  using Values = std::map<std::uint32_t, std::uint64_t>;
  bool ValSet(const std::vector<std::uint8_t>& payload);
  std::optional<std::vector<std::uint8_t>> ValGet(const std::vector<std::uint8_t>& payload) const;
  bool ValDel(const std::vector<std::uint8_t>& payload);
  void Apply(std::uint8_t layers, const Values& values);
  Values ram_, bbr_, flash_;
  std::optional<Values> staged_;  // an open VALSET transaction
  std::uint8_t staged_layers_ = 0;
};

}  // namespace hil::gnss::ubx

#pragma once
/// @file
/// @system
/// name: UbxCfgSession (configuration state machine of a u-blox 5)
/// input: CFG-class UBX messages and `$PUBX,40` / `$PUBX,41` sentences from the host
/// output: polled CFG messages, ACK-ACK / ACK-NAK, effects on the receiver (baud, rates, reset)
/// rate: on host input
/// @endsystem
///
/// Holds the receiver's current configuration (RAM), the saved copy (battery-backed RAM; a
/// NEO-5M has no flash) and the defaults, and applies the u-blox rules (shared/reference/
/// ublox5.md §2.3): every CFG input is answered by ACK-ACK or ACK-NAK; a poll (empty payload, or
/// the selector form of CFG-PRT and CFG-MSG) returns the message followed by ACK-ACK; invalid
/// values, unknown messages and CFG messages a u-blox 5 lacks (CFG-TP5, CFG-GNSS, ...) are NAKed.
/// CFG-CFG sections: ioPort → ports; msgConf → message rates; navConf → RATE, NAV5, SBAS, TP,
/// NMEA (this grouping of navConf is the emulator's choice, UNVERIFIED for u-blox 5).

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/gnss/fix_state.h"

namespace hil::gnss::ubx {

/// Port numbering of CFG-PRT / CFG-MSG: 0 DDC, 1 UART1, 2 UART2, 3 USB, 4 SPI.
inline constexpr int kNumPorts = 5;
inline constexpr int kUart1 = 1;
/// Protocol mask bits (CFG-PRT in/outProtoMask).
inline constexpr std::uint16_t kProtoUbx = 0x01, kProtoNmea = 0x02, kProtoRtcm = 0x04;

struct PortSettings {
  std::uint32_t mode = 0x000008D0;  ///< 8N1
  std::uint32_t baud = 9600;
  std::uint16_t in_mask = kProtoUbx | kProtoNmea | kProtoRtcm;
  std::uint16_t out_mask = kProtoUbx | kProtoNmea;
};

/// The whole configuration of the receiver.
struct ReceiverSettings {
  std::array<PortSettings, kNumPorts> ports{};
  /// rates[(class << 8) | id][target] — per navigation solution, 6 targets (5 ports + reserved)
  std::map<std::uint16_t, std::array<std::uint8_t, 6>> rates;
  std::uint16_t meas_rate_ms = 1000, nav_rate = 1, time_ref = 0;
  std::array<std::uint8_t, 36> nav5{};  ///< CFG-NAV5 payload as polled
  std::array<std::uint8_t, 8> sbas{};   ///< CFG-SBAS payload
  std::array<std::uint8_t, 20> tp{};    ///< CFG-TP payload
  std::array<std::uint8_t, 4> nmea{};   ///< CFG-NMEA payload

  /// Output rate of a message on UART1 (0 = off).
  int Rate(std::uint8_t cls, std::uint8_t id) const;
  void SetRate(std::uint8_t cls, std::uint8_t id, int target, std::uint8_t rate);
  FixMode fix_mode() const;
  double min_elevation_deg() const;
  bool sbas_enabled() const { return (sbas[0] & 0x01) != 0; }
  bool sbas_used_for_corrections() const { return sbas_enabled() && (sbas[1] & 0x02) != 0; }
  int nmea_num_sv() const { return nmea[2]; }
  bool nmea_v23() const { return nmea[1] != 0x21; }

  /// u-blox 5 defaults with the given UART1 baud, measurement period and default NMEA rates.
  static ReceiverSettings Defaults(std::uint32_t baud, std::uint16_t meas_rate_ms,
                                   const std::map<std::uint8_t, std::uint8_t>& nmea_rates);
};

/// What a handled command asks of the receiver beyond its replies.
struct CfgEffects {
  std::optional<StartKind> restart;  ///< CFG-RST: restart navigation with this start kind
  bool hardware_reset = false;  ///< CFG-RST: controlled/HW reset (configuration from BBR, banner)
  bool gps_stop = false, gps_start = false;
};

/// One reply message: framed bytes and a diagnostic name.
struct Reply {
  std::string bytes;
  std::string name;
};

class CfgReplies;  // the replies to one CFG message (ubx_cfg_session.cc)

class UbxCfgSession {
 public:
  /// @param max_rate_hz highest navigation rate CFG-RATE is acknowledged and run at (a shorter
  ///        measRate is NAKed; ReceiverProfile::cfg_rate_max_hz)
  UbxCfgSession(const ReceiverSettings& defaults, double max_rate_hz);

  /// Handles CFG message `id` arriving on port `port_id`; returns its replies in order.
  std::vector<Reply> Handle(std::uint8_t id, const std::vector<std::uint8_t>& payload, int port_id,
                            CfgEffects& fx);
  /// Handles `$PUBX,40` / `$PUBX,41` (body without `$` and checksum). No reply (NMEA commands are
  /// not acknowledged). Returns false when the sentence is malformed or invalid.
  bool HandlePubxSet(const std::string& body);
  /// Reverts the RAM configuration to the saved (battery-backed) one, as a hardware reset does.
  void LoadSaved() { current_ = saved_; }

  const ReceiverSettings& current() const { return current_; }
  ReceiverSettings& current() { return current_; }

 private:
  std::vector<std::uint8_t> PortBlock(int port_id) const;
  bool Known(std::uint8_t cls, std::uint8_t id) const;
  void CopySections(const ReceiverSettings& from, ReceiverSettings& to, std::uint32_t mask) const;
  // one CFG message each (Handle dispatches)
  void HandlePrt(const std::vector<std::uint8_t>& payload, int port_id, CfgReplies& out);
  void HandleMsg(const std::vector<std::uint8_t>& payload, int port_id, CfgReplies& out);
  void HandleRate(const std::vector<std::uint8_t>& payload, CfgReplies& out);
  void HandleNav5(const std::vector<std::uint8_t>& payload, CfgReplies& out);
  void HandleRst(const std::vector<std::uint8_t>& payload, CfgReplies& out, CfgEffects& fx);

  ReceiverSettings defaults_, current_, saved_;
  double max_rate_hz_;
};

/// Supported UART baud rates.
bool IsSupportedBaud(std::uint32_t baud);

}  // namespace hil::gnss::ubx

#pragma once
/// @file
/// UBX output messages of a u-blox 5 built from one NavEpoch: the NAV class (POSECEF, POSLLH,
/// STATUS, DOP, SOL, VELNED, VELECEF, TIMEGPS, TIMEUTC, CLOCK, SVINFO), MON-VER, MON-HW and the
/// ACK class. Every function returns the payload; ubx::Frame() frames it. Layouts and units:
/// shared/reference/ublox5.md §2 (offsets in the comments of the implementation). Messages a u-blox
/// 5 does not have (NAV-PVT, NAV-SAT, ...) do not exist here.

#include <cstdint>
#include <string>
#include <vector>

#include "hil/firmware_emu/gnss/nav_epoch.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"

namespace hil::gnss::ubx {

/// Message ids of the NAV class.
enum NavId : std::uint8_t {
  kNavPosEcef = 0x01,
  kNavPosLlh = 0x02,
  kNavStatus = 0x03,
  kNavDop = 0x04,
  kNavSol = 0x06,
  kNavVelEcef = 0x11,
  kNavVelNed = 0x12,
  kNavTimeGps = 0x20,
  kNavTimeUtc = 0x21,
  kNavClock = 0x22,
  kNavSvInfo = 0x30
};
enum MonId : std::uint8_t { kMonVer = 0x04, kMonHw = 0x09 };
enum AckId : std::uint8_t { kAckNak = 0x00, kAckAck = 0x01 };

/// The NAV messages in the order the emulator sends them within an epoch (by id; the u-blox 5
/// order is UNVERIFIED, a u-blox 7 capture shows the messages grouped by class).
inline constexpr std::uint8_t kNavOutputOrder[] = {
    kNavPosEcef, kNavPosLlh,  kNavStatus,  kNavDop,   kNavSol,   kNavVelEcef,
    kNavVelNed,  kNavTimeGps, kNavTimeUtc, kNavClock, kNavSvInfo};

/// Name for diagnostics, e.g. "UBX-NAV-SOL"; "UBX-xx-yy" for unnamed ids.
std::string MessageName(std::uint8_t cls, std::uint8_t id);

/// Payload of NAV message `id` for the epoch; empty vector for an id this receiver lacks.
std::vector<std::uint8_t> EncodeNav(std::uint8_t id, const NavEpoch& e);

/// MON-VER: software version (CH[30]), hardware version (CH[10]), extensions (CH[30] each).
std::vector<std::uint8_t> EncodeMonVer(const std::string& sw, const std::string& hw,
                                       const std::vector<std::string>& extensions);
/// MON-HW, 68-byte layout (u-blox 5/6): antenna OK and powered, RTC calibrated, a plausible AGC
/// count and noise level.
std::vector<std::uint8_t> EncodeMonHw(std::uint32_t used_mask);
/// ACK-ACK / ACK-NAK for the message (cls, id).
std::string Ack(bool ok, std::uint8_t cls, std::uint8_t id);

}  // namespace hil::gnss::ubx

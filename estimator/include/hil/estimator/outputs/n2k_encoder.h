#pragma once
/// @file
/// NMEA 2000 encoders of the fused solution (layouts after canboat's database; bit fields LSB
/// first, little-endian; all-ones = not available):
///   129025 Position Rapid Update (single frame), 129026 COG & SOG Rapid Update (single frame),
///   129029 GNSS Position Data (fast packet, 43 bytes with no reference stations),
///   127250 Vessel Heading (single frame), 127257 Attitude (single frame).
/// CAN ID = priority << 26 | PGN << 8 | source address (PDU2, no destination). Frames can be
/// written in can-utils `candump -l` form for canplayer and canboat's analyzer.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace hil::estimator::outputs {

/// One classic CAN frame with a 29-bit identifier.
struct CanFrame {
  std::uint32_t id = 0;
  std::uint8_t len = 8;
  std::array<std::uint8_t, 8> data{};
};

/// Up to 32 frames of one fast-packet message (no allocation).
struct FastPacket {
  std::array<CanFrame, 32> frames{};
  int count = 0;
};

/// 29-bit identifier of a PDU2 PGN.
std::uint32_t N2kCanId(std::uint32_t pgn, int priority, std::uint8_t source);

CanFrame EncodePositionRapid(double lat_deg, double lon_deg, std::uint8_t source);
/// `cog_rad` true course over ground in [0, 2π), `sog_mps` speed over ground.
CanFrame EncodeCogSogRapid(std::uint8_t sid, double cog_rad, double sog_mps, std::uint8_t source);
/// `days` since 1970 and `seconds_of_day` UTC; `alt` (m) above the WGS-84 ellipsoid; `method`
/// 0 none, 1 GNSS, 2 DGNSS, 4 RTK fixed, 5 RTK float, 6 estimated (dead reckoning). What the
/// receiver did not report goes out as "not available": `num_sv` < 0, `hdop` <= 0, no
/// `geoid_separation_m` (the geoid's height above the ellipsoid, as in GGA).
FastPacket EncodeGnssPosition(std::uint8_t sid, std::uint16_t days, double seconds_of_day,
                              double lat, double lon, double alt, int method, int num_sv,
                              double hdop, std::uint8_t fast_packet_sequence, std::uint8_t source,
                              std::optional<double> geoid_separation_m = std::nullopt);
/// True heading (radians clockwise from north, [0, 2π)).
CanFrame EncodeVesselHeading(std::uint8_t sid, double heading_rad, std::uint8_t source);
/// Yaw (clockwise from north), pitch (nose up), roll (right side down), radians.
CanFrame EncodeAttitude(std::uint8_t sid, double yaw_rad, double pitch_rad, double roll_rad,
                        std::uint8_t source);

/// "(secs.micros) IFACE IIIIIIII#HEX\n", the `candump -l` log line.
std::string CandumpLine(const CanFrame& f, std::int64_t unix_us, const std::string& iface);

}  // namespace hil::estimator::outputs

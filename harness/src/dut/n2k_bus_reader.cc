#include "hil/harness/dut/n2k_bus_reader.h"

#include <cmath>
#include <string>

#include "hil/firmware_emu/little_endian.h"

namespace hil::harness {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

}  // namespace

std::optional<EstimateRecord> N2kBusReader::Frame(std::uint32_t id29, std::string_view data,
                                                  WallTime wall) {
  const std::uint32_t pgn = N2kPgnFromId(id29);
  ++per_pgn_[pgn];
  if (data.empty()) return std::nullopt;
  switch (pgn) {
    case 129026:  // SID, COG reference (bits 0-1), COG u16 1e-4 rad, SOG u16 0.01 m/s
      if (data.size() >= 6 && LeRead<std::uint16_t>(data, 2) != 0xFFFF &&
          LeRead<std::uint16_t>(data, 4) != 0xFFFF) {
        cog_sog_ = {static_cast<unsigned char>(data[0]),
                    static_cast<double>(LeRead<std::uint16_t>(data, 2)) * 1e-4,
                    static_cast<double>(LeRead<std::uint16_t>(data, 4)) * 0.01};
      }
      return std::nullopt;
    case 127250:  // SID, heading u16 1e-4 rad
      if (data.size() >= 3 && LeRead<std::uint16_t>(data, 1) != 0xFFFF) {
        heading_ = {static_cast<unsigned char>(data[0]),
                    static_cast<double>(LeRead<std::uint16_t>(data, 1)) * 1e-4, 0};
      }
      return std::nullopt;
    case 129029:
      break;
    default:
      return std::nullopt;
  }
  const auto payload = fast_.Add(N2kSourceFromId(id29), pgn, data);
  if (!payload || payload->size() < 31) return std::nullopt;
  const std::string& b = *payload;
  const std::uint64_t days = LeRead<std::uint16_t>(b, 1), tod = LeRead<std::uint32_t>(b, 3);
  if (days == 0xFFFF || tod == 0xFFFFFFFF) return std::nullopt;
  EstimateRecord r;
  const std::int64_t t_ns =
      static_cast<std::int64_t>(days) * kDayNs + static_cast<std::int64_t>(tod) * 100000LL;
  r.t_validity = TimeFromNs(t_ns - ToNs(start_));
  r.lat_deg = static_cast<double>(LeRead<std::int64_t>(b, 7)) * 1e-16;
  r.lon_deg = static_cast<double>(LeRead<std::int64_t>(b, 15)) * 1e-16;
  r.height_m = static_cast<double>(LeRead<std::int64_t>(b, 23)) * 1e-6;
  r.wall_rx = wall;
  const int sid = static_cast<unsigned char>(b[0]);
  if (cog_sog_.sid == sid) {
    r.vel_enu_mps =
        Eigen::Vector3d(cog_sog_.b * std::sin(cog_sog_.a), cog_sog_.b * std::cos(cog_sog_.a), 0.0);
  }
  if (heading_.sid == sid) r.yaw_deg = std::fmod(heading_.a * kRadToDeg + 360.0, 360.0);
  return r;
}

}  // namespace hil::harness

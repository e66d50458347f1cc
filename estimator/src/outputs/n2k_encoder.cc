#include "hil/estimator/outputs/n2k_encoder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hil::estimator::outputs {
namespace {

void Put(std::uint8_t* p, std::uint64_t v, int n) {
  for (int i = 0; i < n; ++i) p[i] = static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF);
}
std::int64_t Round(double v) { return static_cast<std::int64_t>(std::llround(v)); }
std::uint16_t Angle16(double rad) {  // unsigned 1e-4 rad in [0, 2π)
  double a = std::fmod(rad, 2 * M_PI);
  if (a < 0) a += 2 * M_PI;
  return static_cast<std::uint16_t>(std::min<std::int64_t>(Round(a * 1e4), 62831));
}
std::uint16_t SignedAngle16(double rad) {  // signed 1e-4 rad
  const double a = std::remainder(rad, 2 * M_PI);
  return static_cast<std::uint16_t>(static_cast<std::int16_t>(Round(a * 1e4)));
}

}  // namespace

std::uint32_t N2kCanId(std::uint32_t pgn, int priority, std::uint8_t source) {
  return (static_cast<std::uint32_t>(priority & 7) << 26) | ((pgn & 0x3FFFF) << 8) | source;
}

CanFrame EncodePositionRapid(double lat, double lon, std::uint8_t source) {
  CanFrame f;
  f.id = N2kCanId(129025, 2, source);
  Put(&f.data[0], static_cast<std::uint32_t>(static_cast<std::int32_t>(Round(lat * 1e7))), 4);
  Put(&f.data[4], static_cast<std::uint32_t>(static_cast<std::int32_t>(Round(lon * 1e7))), 4);
  return f;
}

CanFrame EncodeCogSogRapid(std::uint8_t sid, double cog_rad, double sog_mps, std::uint8_t source) {
  CanFrame f;
  f.id = N2kCanId(129026, 2, source);
  f.data[0] = sid;
  f.data[1] = 0xFC;  // reference 0 (true), reserved bits set
  Put(&f.data[2], Angle16(cog_rad), 2);
  Put(&f.data[4],
      static_cast<std::uint16_t>(std::clamp<std::int64_t>(Round(sog_mps * 100), 0, 65532)), 2);
  f.data[6] = f.data[7] = 0xFF;
  return f;
}

FastPacket EncodeGnssPosition(std::uint8_t sid, std::uint16_t days, double seconds_of_day,
                              double lat, double lon, double alt, int method, int num_sv,
                              double hdop, std::uint8_t fast_packet_sequence, std::uint8_t source,
                              std::optional<double> geoid_separation_m) {
  std::array<std::uint8_t, 43> p{};
  p[0] = sid;
  Put(&p[1], days, 2);
  Put(&p[3], static_cast<std::uint32_t>(Round(seconds_of_day * 1e4)), 4);
  Put(&p[7], static_cast<std::uint64_t>(Round(lat * 1e16)), 8);
  Put(&p[15], static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(lon * 1e16))), 8);
  Put(&p[23], static_cast<std::uint64_t>(Round(alt * 1e6)), 8);
  p[31] = static_cast<std::uint8_t>(0 | ((method & 0xF) << 4));  // GNSS type 0 (GPS), method
  p[32] = 0xFC;                                                  // integrity 0, reserved set
  p[33] = num_sv < 0 ? 0xFF : static_cast<std::uint8_t>(std::clamp(num_sv, 0, 252));
  const std::int64_t hdop_raw =
      hdop > 0 ? std::clamp<std::int64_t>(Round(hdop * 100), 0, 32764) : 0x7FFF;  // not available
  Put(&p[34], static_cast<std::uint16_t>(hdop_raw), 2);
  Put(&p[36], 0x7FFF, 2);  // PDOP not available
  const std::int64_t n_raw =
      geoid_separation_m ? std::clamp<std::int64_t>(Round(*geoid_separation_m * 100), -2147483647,
                                                    2147483646)
                         : 0x7FFFFFFF;  // not available
  Put(&p[38], static_cast<std::uint32_t>(static_cast<std::int32_t>(n_raw)), 4);
  p[42] = 0;  // no reference stations
  FastPacket fp;
  const std::uint32_t id = N2kCanId(129029, 3, source);
  std::size_t used = 0;
  for (int frame = 0; used < p.size(); ++frame) {
    CanFrame& f = fp.frames[static_cast<std::size_t>(frame)];
    f.id = id;
    f.data.fill(0xFF);
    f.data[0] = static_cast<std::uint8_t>(((fast_packet_sequence & 7) << 5) | (frame & 0x1F));
    std::size_t at = 1;
    if (frame == 0) f.data[at++] = static_cast<std::uint8_t>(p.size());
    while (at < 8 && used < p.size()) f.data[at++] = p[used++];
    fp.count = frame + 1;
  }
  return fp;
}

CanFrame EncodeVesselHeading(std::uint8_t sid, double heading_rad, std::uint8_t source) {
  CanFrame f;
  f.id = N2kCanId(127250, 2, source);
  f.data[0] = sid;
  Put(&f.data[1], Angle16(heading_rad), 2);
  Put(&f.data[3], 0x7FFF, 2);  // deviation n/a
  Put(&f.data[5], 0x7FFF, 2);  // variation n/a
  f.data[7] = 0xFC;            // reference 0 (true), reserved set
  return f;
}

CanFrame EncodeAttitude(std::uint8_t sid, double yaw, double pitch, double roll,
                        std::uint8_t source) {
  CanFrame f;
  f.id = N2kCanId(127257, 3, source);
  f.data[0] = sid;
  Put(&f.data[1], SignedAngle16(yaw), 2);
  Put(&f.data[3], SignedAngle16(pitch), 2);
  Put(&f.data[5], SignedAngle16(roll), 2);
  f.data[7] = 0xFF;
  return f;
}

std::string CandumpLine(const CanFrame& f, std::int64_t unix_us, const std::string& iface) {
  char buf[96];
  int n = std::snprintf(buf, sizeof buf, "(%lld.%06lld) %s %08X#",
                        static_cast<long long>(unix_us / 1000000),
                        static_cast<long long>(unix_us % 1000000), iface.c_str(), f.id);
  std::string s(buf, static_cast<std::size_t>(n));
  for (int i = 0; i < f.len; ++i) {
    n = std::snprintf(buf, sizeof buf, "%02X", f.data[static_cast<std::size_t>(i)]);
    s.append(buf, static_cast<std::size_t>(n));
  }
  return s + "\n";
}

}  // namespace hil::estimator::outputs

#include "hil/firmware_emu/rtk/rtcm3_station.h"

#include <cmath>
#include <stdexcept>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

namespace hil::rtcm3 {
namespace {

constexpr double kArpUnit_m = 0.0001;  // DF025–DF028 resolution

std::int64_t Scaled(double value_m, int bits, const char* field) {
  const auto v = static_cast<std::int64_t>(std::llround(value_m / kArpUnit_m));
  const std::int64_t limit = std::int64_t{1} << (bits - 1);
  if (v < -limit || v >= limit) throw std::out_of_range(std::string("RTCM 3 field ") + field);
  return v;
}

std::string Encode(const StationInfo& s, int number) {
  if (s.station_id < 0 || s.station_id > 4095) throw std::out_of_range("RTCM 3 DF003");
  if (s.itrf_year < 0 || s.itrf_year > 63) throw std::out_of_range("RTCM 3 DF021");
  BitWriter w;
  w.PutUnsigned(static_cast<std::uint64_t>(number), 12);
  w.PutUnsigned(static_cast<std::uint64_t>(s.station_id), 12);
  w.PutUnsigned(static_cast<std::uint64_t>(s.itrf_year), 6);
  w.PutUnsigned(s.gps ? 1 : 0, 1);
  w.PutUnsigned(s.glonass ? 1 : 0, 1);
  w.PutUnsigned(s.galileo ? 1 : 0, 1);
  w.PutUnsigned(0, 1);  // DF141: a physical reference station, not a virtual one
  w.PutSigned(Scaled(s.arp_E_m.x(), 38, "DF025"), 38);
  w.PutUnsigned(s.single_oscillator ? 1 : 0, 1);
  w.PutUnsigned(0, 1);  // DF001 reserved
  w.PutSigned(Scaled(s.arp_E_m.y(), 38, "DF026"), 38);
  w.PutUnsigned(static_cast<std::uint64_t>(s.quarter_cycle & 3), 2);
  w.PutSigned(Scaled(s.arp_E_m.z(), 38, "DF027"), 38);
  if (number == 1006) {
    const std::int64_t h = std::llround(s.antenna_height_m / kArpUnit_m);
    if (h < 0 || h > 65535) throw std::out_of_range("RTCM 3 DF028");
    w.PutUnsigned(static_cast<std::uint64_t>(h), 16);
  }
  return w.bytes();
}

}  // namespace

std::string Encode1005(const StationInfo& s) { return Encode(s, 1005); }
std::string Encode1006(const StationInfo& s) { return Encode(s, 1006); }

StationInfo DecodeStation(const std::string& body) {
  const int number = MessageNumber(body);
  if ((number != 1005 || body.size() != 19) && (number != 1006 || body.size() != 21)) {
    throw std::invalid_argument("not a 1005/1006 body: message " + std::to_string(number) + ", " +
                                std::to_string(body.size()) + " bytes");
  }
  BitReader r(body);
  StationInfo s;
  r.GetUnsigned(12);
  s.station_id = static_cast<int>(r.GetUnsigned(12));
  s.itrf_year = static_cast<int>(r.GetUnsigned(6));
  s.gps = r.GetUnsigned(1) != 0;
  s.glonass = r.GetUnsigned(1) != 0;
  s.galileo = r.GetUnsigned(1) != 0;
  r.GetUnsigned(1);
  s.arp_E_m.x() = static_cast<double>(r.GetSigned(38)) * kArpUnit_m;
  s.single_oscillator = r.GetUnsigned(1) != 0;
  r.GetUnsigned(1);
  s.arp_E_m.y() = static_cast<double>(r.GetSigned(38)) * kArpUnit_m;
  s.quarter_cycle = static_cast<int>(r.GetUnsigned(2));
  s.arp_E_m.z() = static_cast<double>(r.GetSigned(38)) * kArpUnit_m;
  if (number == 1006) s.antenna_height_m = static_cast<double>(r.GetUnsigned(16)) * kArpUnit_m;
  return s;
}

}  // namespace hil::rtcm3

#include "hil/firmware_emu/rtk/rtcm3_moving_base.h"

#include <cmath>
#include <stdexcept>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

namespace hil::rtcm3 {
namespace {

constexpr double kPositionUnit_m = 0.0001;  // as DF025–DF027

std::int64_t Scaled38(double value_m) {
  const auto v = static_cast<std::int64_t>(std::llround(value_m / kPositionUnit_m));
  constexpr std::int64_t kLimit = std::int64_t{1} << 37;
  if (v < -kLimit || v >= kLimit) throw std::out_of_range("RTCM 3 4072.0 antenna position");
  return v;
}

}  // namespace

std::string Encode4072Pvt(const MovingBasePvt& p) {
  if (p.station_id < 0 || p.station_id > 4095) throw std::out_of_range("RTCM 3 4072.0 DF003");
  if (p.epoch_ms >= 604800000U) throw std::out_of_range("RTCM 3 4072.0 epoch time");
  BitWriter w;
  w.PutUnsigned(kMovingBaseMessage, 12);
  w.PutUnsigned(kMovingBaseSubtype, 12);
  w.PutUnsigned(static_cast<std::uint64_t>(p.station_id), 12);
  w.PutUnsigned(p.epoch_ms, 30);
  for (int k = 0; k < 3; ++k) w.PutSigned(Scaled38(p.antenna_E_m[k]), 38);
  return w.bytes();
}

int Subtype4072(const std::string& body) {
  if (body.size() < 3 || MessageNumber(body) != kMovingBaseMessage) return -1;
  BitReader r(body);
  r.GetUnsigned(12);
  return static_cast<int>(r.GetUnsigned(12));
}

MovingBasePvt Decode4072Pvt(const std::string& body) {
  if (Subtype4072(body) != kMovingBaseSubtype || body.size() != kMovingBasePvtBytes)
    throw std::invalid_argument("not a 4072.0 body: " + std::to_string(body.size()) + " bytes");
  BitReader r(body);
  r.GetUnsigned(24);
  MovingBasePvt p;
  p.station_id = static_cast<int>(r.GetUnsigned(12));
  p.epoch_ms = static_cast<std::uint32_t>(r.GetUnsigned(30));
  for (int k = 0; k < 3; ++k)
    p.antenna_E_m[k] = static_cast<double>(r.GetSigned(38)) * kPositionUnit_m;
  return p;
}

}  // namespace hil::rtcm3

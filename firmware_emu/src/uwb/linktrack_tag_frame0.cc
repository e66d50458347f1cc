#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "hil/firmware_emu/little_endian.h"

namespace hil::linktrack {
namespace {

std::int64_t RoundSat(double v, double scale, std::int64_t lo, std::int64_t hi) {
  if (!std::isfinite(v)) return 0;
  const double r = std::round(v * scale);
  return r <= static_cast<double>(lo)   ? lo
         : r >= static_cast<double>(hi) ? hi
                                        : static_cast<std::int64_t>(r);
}

void PutInt24(std::string& b, std::size_t at, double v, double scale) {
  LePut(b, at, static_cast<std::uint64_t>(RoundSat(v, scale, -8388608, 8388607)) & 0xFFFFFFu, 3);
}
void PutFloat(std::string& b, std::size_t at, float v) {
  LePut(b, at, std::bit_cast<std::uint32_t>(v), 4);
}

}  // namespace

std::uint8_t NlinkSum8(const char* p, std::size_t n) {
  unsigned s = 0;
  for (std::size_t i = 0; i < n; ++i) s += static_cast<unsigned char>(p[i]);
  return static_cast<std::uint8_t>(s & 0xFFu);
}

std::string EncodeTagFrame0(const TagFrame0& f) {
  using namespace tag_frame0;
  std::string b(kTagFrame0Size, '\0');
  b[0] = static_cast<char>(kTagFrame0Header);
  b[1] = static_cast<char>(kTagFrame0Mark);
  b[kId] = static_cast<char>(f.id);
  b[kRole] = static_cast<char>(f.role);
  for (int k = 0; k < 3; ++k) {
    PutInt24(b, kPos + 3 * k, f.p_m[k], 1000.0);
    PutInt24(b, kVel + 3 * k, f.v_mps[k], 10000.0);
    PutFloat(b, kGyro + 4 * k, f.gyro_radps[k]);
    PutFloat(b, kAcc + 4 * k, f.acc_mps2[k]);
    LePut(b, kAngle + 2 * k,
          static_cast<std::uint64_t>(RoundSat(f.angle_deg[k], 100.0, -32768, 32767)) & 0xFFFFu, 2);
    b[kEop + k] = static_cast<char>(RoundSat(f.eop_m[k], 100.0, 0, 255));
  }
  for (int k = 0; k < 8; ++k) PutInt24(b, kDis + 3 * k, f.dis_m[k], 1000.0);
  for (int k = 0; k < 4; ++k) PutFloat(b, kQuat + 4 * k, f.quat_wxyz[k]);
  LePut(b, kLocalTime, f.local_time_ms, 4);
  LePut(b, kSystemTime, f.system_time_ms, 4);
  LePut(b, kVoltage, static_cast<std::uint64_t>(RoundSat(f.voltage_v, 1000.0, 0, 65535)), 2);
  b[kCheck] = static_cast<char>(NlinkSum8(b.data(), kCheck));
  return b;
}

}  // namespace hil::linktrack

#include "hil/firmware_emu/uwb/uwb_tdoa_frame.h"

#include <cmath>

#include "hil/firmware_emu/little_endian.h"
#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"

namespace hil::uwb {

std::int32_t TdoaPicoseconds(double r_i1_m) {
  const double ps = std::round(r_i1_m / kTdoaSpeedOfLight_mps * 1e12);
  if (!std::isfinite(ps)) return 0;
  return ps <= -2147483648.0  ? INT32_MIN
         : ps >= 2147483647.0 ? INT32_MAX
                              : static_cast<std::int32_t>(ps);
}

std::string EncodeTdoaFrame(const TdoaFrame& f) {
  std::string b(kTdoaFrameSize, '\0');
  const auto put = [&b](std::size_t at, std::uint32_t v) { LePut(b, at, v, 4); };
  b[0] = static_cast<char>(kTdoaFrameHeader);
  b[1] = static_cast<char>(kTdoaFrameMark);
  b[2] = static_cast<char>(f.id);
  b[3] = static_cast<char>(kTdoaDifferences);
  put(4, f.system_time_ms);
  for (std::size_t i = 0; i < kTdoaDifferences; ++i)
    put(8 + 4 * i, static_cast<std::uint32_t>(f.t_i1_ps[i]));
  b[kTdoaFrameSize - 1] = static_cast<char>(linktrack::NlinkSum8(b.data(), kTdoaFrameSize - 1));
  return b;
}

}  // namespace hil::uwb

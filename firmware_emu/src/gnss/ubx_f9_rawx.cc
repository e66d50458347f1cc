#include "hil/firmware_emu/gnss/ubx_f9_rawx.h"

#include <algorithm>
#include <cmath>

#include "hil/firmware_emu/gnss/ubx_frame.h"

namespace hil::gnss::ubx {
namespace {

// The 4-bit code n of a standard deviation in steps of unit × 2^n (the smallest n ≥ it).
std::uint8_t Log2Code(double sigma, double unit) {
  if (!(sigma > unit)) return 0;
  return static_cast<std::uint8_t>(std::clamp(std::ceil(std::log2(sigma / unit)), 0.0, 15.0));
}

// The 4-bit code n of a standard deviation in steps of unit × n.
std::uint8_t LinearCode(double sigma, double unit) {
  if (!(sigma > 0)) return 0;
  return static_cast<std::uint8_t>(std::clamp(std::ceil(sigma / unit), 0.0, 15.0));
}

}  // namespace

std::vector<std::uint8_t> EncodeRxmRawx(const RawxEpoch& e) {
  Writer w;
  const std::size_t n = std::min<std::size_t>(e.meas.size(), 255);
  std::uint8_t rec_stat = 0;
  if (e.leap_valid) rec_stat |= 1U;                                             // leapSec
  if (e.clk_reset) rec_stat |= 2U;                                              // clkReset
  w.R8(e.rcv_tow_s).U2(e.week).I1(e.leap_s).U1(n).U1(rec_stat).U1(1).Zeros(2);  // 0–15
  for (std::size_t k = 0; k < n; ++k) {
    const RawxMeasurement& m = e.meas[k];
    w.R8(m.pr_m).R8(m.cp_cycles).R4(static_cast<float>(m.do_hz));  // 16 + 0, 8, 16
    w.U1(m.gnss_id).U1(m.sv_id).U1(m.sig_id).U1(m.freq_id);        // 20–23
    w.U2(static_cast<std::uint64_t>(std::clamp(m.locktime_ms, 0.0, kRawxMaxLocktime_ms)));
    w.U1(static_cast<std::uint64_t>(std::clamp(std::lround(m.cno_dbhz), 0L, 255L)));  // 26 cno
    w.U1(Log2Code(m.pr_sigma_m, 0.01))                                                // 27
        .U1(LinearCode(m.cp_sigma_cycles, 0.004))                                     // 28
        .U1(Log2Code(m.do_sigma_hz, 0.002));                                          // 29
    std::uint8_t trk = 0;
    if (m.pr_valid) trk |= 1U;
    if (m.cp_valid) trk |= 2U;
    if (m.cp_valid && m.half_cyc) trk |= 4U;
    w.U1(trk).U1(0);  // 30 trkStat, 31 reserved
  }
  return w.bytes();
}

}  // namespace hil::gnss::ubx

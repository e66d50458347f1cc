#include "hil/firmware_emu/rtk/rtcm3_msm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"

namespace hil::rtcm3 {
namespace {

constexpr int kGpsMsmBase = 1070;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRoughUnit_ms = 1.0 / 1024.0;  // DF398

// Resolution (ms or m/s), width and invalid marker of the signal fields of one MSM kind.
struct SignalLayout {
  double pr_unit_ms;
  int pr_bits;
  double cp_unit_ms;
  int cp_bits;
  int lock_bits, cnr_bits;
  double cnr_unit_dbhz;
};

SignalLayout LayoutOf(MsmKind kind) {
  if (kind == MsmKind::kMsm4)
    return {std::ldexp(1.0, -24), 15, std::ldexp(1.0, -29), 22, 4, 6, 1.0};
  return {std::ldexp(1.0, -29), 20, std::ldexp(1.0, -31), 24, 10, 10, 1.0 / 16.0};
}

// The two's complement field of `value / unit` in `bits`, or the invalid marker (most negative)
// when the value is NaN or does not fit.
std::int64_t FineField(double value, double unit, int bits) {
  const std::int64_t invalid = -(std::int64_t{1} << (bits - 1));
  if (!std::isfinite(value)) return invalid;
  const double q = std::round(value / unit);
  if (q <= static_cast<double>(invalid) || q >= static_cast<double>(-invalid)) return invalid;
  return static_cast<std::int64_t>(q);
}

void CheckEpoch(const MsmEpoch& e, std::uint64_t& sat_mask, std::uint32_t& sig_mask) {
  sat_mask = 0;
  sig_mask = 0;
  int last_sat = 0;
  for (const MsmSatellite& s : e.satellites) {
    if (s.id < 1 || s.id > 64 || s.id <= last_sat)
      throw std::invalid_argument("MSM satellite ids must be ascending in 1-64");
    last_sat = s.id;
    sat_mask |= std::uint64_t{1} << (64 - s.id);
    int last_sig = 0;
    for (const MsmSignal& g : s.signals) {
      if (g.signal_id < 1 || g.signal_id > 32 || g.signal_id <= last_sig)
        throw std::invalid_argument("MSM signal ids must be ascending in 1-32");
      last_sig = g.signal_id;
      sig_mask |= std::uint32_t{1} << (32 - g.signal_id);
    }
  }
}

std::vector<int> MaskIds(std::uint64_t mask, int bits) {
  std::vector<int> ids;
  for (int i = 1; i <= bits; ++i) {
    if ((mask >> (bits - i)) & 1U) ids.push_back(i);
  }
  return ids;
}

const MsmSignal* FindSignal(const MsmSatellite& s, int signal_id) {
  for (const MsmSignal& g : s.signals) {
    if (g.signal_id == signal_id) return &g;
  }
  return nullptr;
}

// Rough range (ms, a multiple of 2^-10 ms) of a satellite: its first valid pseudorange rounded;
// NaN when none is valid or it is beyond 255 ms.
double RoughRange_ms(const MsmSatellite& s) {
  for (const MsmSignal& g : s.signals) {
    if (!std::isfinite(g.pseudorange_m)) continue;
    const double r = std::round(g.pseudorange_m / kLightMs_m / kRoughUnit_ms) * kRoughUnit_ms;
    return (r >= 0 && r < 255.0) ? r : kNaN;
  }
  return kNaN;
}

// Rough phaserange rate (whole m/s) of a satellite: its first valid rate rounded.
double RoughRate_mps(const MsmSatellite& s) {
  for (const MsmSignal& g : s.signals) {
    if (std::isfinite(g.phaserange_rate_mps)) {
      const double r = std::round(g.phaserange_rate_mps);
      return std::abs(r) < 8191 ? r : kNaN;
    }
  }
  return kNaN;
}

void PutHeader(BitWriter& w, const MsmEpoch& e, MsmKind kind, std::uint64_t sat_mask,
               std::uint32_t sig_mask) {
  w.PutUnsigned(static_cast<std::uint64_t>(kGpsMsmBase + static_cast<int>(kind)), 12);
  w.PutUnsigned(static_cast<std::uint64_t>(e.station_id & 0xFFF), 12);
  w.PutUnsigned(e.epoch_time_ms, 30);
  w.PutUnsigned(e.multiple_message ? 1 : 0, 1);
  w.PutUnsigned(static_cast<std::uint64_t>(e.iods & 7), 3);
  w.PutUnsigned(0, 7);  // DF001 reserved
  w.PutUnsigned(static_cast<std::uint64_t>(e.clock_steering & 3), 2);
  w.PutUnsigned(static_cast<std::uint64_t>(e.external_clock & 3), 2);
  w.PutUnsigned(e.smoothing ? 1 : 0, 1);
  w.PutUnsigned(static_cast<std::uint64_t>(e.smoothing_interval & 7), 3);
  w.PutUnsigned(sat_mask, 64);
  w.PutUnsigned(sig_mask, 32);
}

void PutSatelliteData(BitWriter& w, const MsmEpoch& e, MsmKind kind) {
  for (const MsmSatellite& s : e.satellites) {
    const double r = RoughRange_ms(s);
    w.PutUnsigned(std::isfinite(r) ? static_cast<std::uint64_t>(std::floor(r)) : 255U, 8);
  }
  if (kind == MsmKind::kMsm7) {
    for (std::size_t i = 0; i < e.satellites.size(); ++i)
      w.PutUnsigned(0, 4);  // DF419: GPS reserved
  }
  for (const MsmSatellite& s : e.satellites) {
    const double r = RoughRange_ms(s);
    const double frac = std::isfinite(r) ? (r - std::floor(r)) / kRoughUnit_ms : 0.0;
    w.PutUnsigned(static_cast<std::uint64_t>(std::lround(frac)), 10);
  }
  if (kind == MsmKind::kMsm7) {
    for (const MsmSatellite& s : e.satellites) {
      const double r = RoughRate_mps(s);
      w.PutSigned(std::isfinite(r) ? static_cast<std::int64_t>(r) : -8192, 14);
    }
  }
}

// The cells in transmission order: satellite by satellite, each satellite's signals in mask order.
std::vector<std::pair<const MsmSatellite*, const MsmSignal*>> Cells(const MsmEpoch& e,
                                                                    std::uint32_t sig_mask) {
  std::vector<std::pair<const MsmSatellite*, const MsmSignal*>> cells;
  for (const MsmSatellite& s : e.satellites) {
    for (const int id : MaskIds(sig_mask, 32)) {
      if (const MsmSignal* g = FindSignal(s, id)) cells.emplace_back(&s, g);
    }
  }
  return cells;
}

void PutSignalData(BitWriter& w, const MsmEpoch& e, MsmKind kind, std::uint32_t sig_mask) {
  const SignalLayout l = LayoutOf(kind);
  const auto cells = Cells(e, sig_mask);
  for (const auto& [s, g] : cells)
    w.PutSigned(
        FineField(g->pseudorange_m / kLightMs_m - RoughRange_ms(*s), l.pr_unit_ms, l.pr_bits),
        l.pr_bits);
  for (const auto& [s, g] : cells)
    w.PutSigned(
        FineField(g->phaserange_m / kLightMs_m - RoughRange_ms(*s), l.cp_unit_ms, l.cp_bits),
        l.cp_bits);
  for (const auto& [s, g] : cells) {
    const int lock = kind == MsmKind::kMsm4 ? LockIndicatorMsm4(g->lock_time_s)
                                            : LockIndicatorMsm7(g->lock_time_s);
    w.PutUnsigned(static_cast<std::uint64_t>(lock), l.lock_bits);
  }
  for (const auto& [s, g] : cells) w.PutUnsigned(g->half_cycle ? 1 : 0, 1);
  const double cnr_max = static_cast<double>((1 << l.cnr_bits) - 1);
  for (const auto& [s, g] : cells) {
    const double q = std::clamp(std::round(g->cnr_dbhz / l.cnr_unit_dbhz), 0.0, cnr_max);
    w.PutUnsigned(static_cast<std::uint64_t>(q), l.cnr_bits);
  }
  if (kind == MsmKind::kMsm7) {
    for (const auto& [s, g] : cells)
      w.PutSigned(FineField(g->phaserange_rate_mps - RoughRate_mps(*s), 0.0001, 15), 15);
  }
}

}  // namespace

std::string EncodeGpsMsm(const MsmEpoch& epoch, MsmKind kind) {
  std::uint64_t sat_mask = 0;
  std::uint32_t sig_mask = 0;
  CheckEpoch(epoch, sat_mask, sig_mask);
  const std::size_t nsig = MaskIds(sig_mask, 32).size();
  if (epoch.satellites.size() * nsig > 64)
    throw std::invalid_argument("MSM cell mask longer than 64 bits");
  BitWriter w;
  PutHeader(w, epoch, kind, sat_mask, sig_mask);
  for (const MsmSatellite& s : epoch.satellites) {
    for (const int id : MaskIds(sig_mask, 32)) w.PutUnsigned(FindSignal(s, id) ? 1 : 0, 1);
  }
  PutSatelliteData(w, epoch, kind);
  PutSignalData(w, epoch, kind, sig_mask);
  return w.bytes();
}

int LockIndicatorMsm4(double lock_time_s) {
  const double ms = std::floor(lock_time_s * 1000.0 + 1e-6);  // 1 ns guard against 0.064 → 63.999…
  if (ms < 32) return 0;
  return std::min(15, static_cast<int>(std::floor(std::log2(ms))) - 4);
}

int LockIndicatorMsm7(double lock_time_s) {
  const auto ms = static_cast<std::int64_t>(std::floor(std::max(0.0, lock_time_s) * 1000.0 + 1e-6));
  if (ms < 64) return static_cast<int>(ms);
  if (ms >= (std::int64_t{1} << 26)) return 704;
  int k = 0;  // block k: 2^(6+k) ≤ ms < 2^(7+k), step 2^(k+1) ms, indicators 64 + 32k…
  while (ms >= (std::int64_t{1} << (7 + k))) ++k;
  return static_cast<int>(64 + 32 * k +
                          (ms - (std::int64_t{1} << (6 + k))) / (std::int64_t{2} << k));
}

double LockTimeOfMsm7Indicator(int indicator) {
  if (indicator < 64) return indicator * 0.001;
  if (indicator >= 704) return std::ldexp(1.0, 26) * 0.001;
  const int k = (indicator - 64) / 32;
  const double ms = std::ldexp(1.0, 6 + k) + (indicator - 64 - 32 * k) * std::ldexp(1.0, k + 1);
  return ms * 0.001;
}

}  // namespace hil::rtcm3

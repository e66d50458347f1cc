// The reader of GPS MSM4/MSM7 bodies (rtcm3_msm.h): the tests' check of what the encoder wrote.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"
#include "hil/firmware_emu/rtk/rtcm3_frame.h"
#include "hil/firmware_emu/rtk/rtcm3_msm.h"

namespace hil::rtcm3 {
namespace {

constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();

double Fine(BitReader& r, int bits, double unit) {
  const std::int64_t v = r.GetSigned(bits);
  return v == -(std::int64_t{1} << (bits - 1)) ? kNotAvailable : static_cast<double>(v) * unit;
}

MsmEpoch ReadHeader(BitReader& r, std::vector<int>& sats, std::vector<int>& sigs,
                    std::vector<bool>& cells) {
  MsmEpoch e;
  r.GetUnsigned(12);
  e.station_id = static_cast<int>(r.GetUnsigned(12));
  e.epoch_time_ms = static_cast<std::uint32_t>(r.GetUnsigned(30));
  e.multiple_message = r.GetUnsigned(1) != 0;
  e.iods = static_cast<int>(r.GetUnsigned(3));
  r.GetUnsigned(7);
  e.clock_steering = static_cast<int>(r.GetUnsigned(2));
  e.external_clock = static_cast<int>(r.GetUnsigned(2));
  e.smoothing = r.GetUnsigned(1) != 0;
  e.smoothing_interval = static_cast<int>(r.GetUnsigned(3));
  for (int i = 1; i <= 64; ++i) {
    if (r.GetUnsigned(1)) sats.push_back(i);
  }
  for (int i = 1; i <= 32; ++i) {
    if (r.GetUnsigned(1)) sigs.push_back(i);
  }
  if (sats.size() * sigs.size() > 64) throw std::invalid_argument("MSM cell mask over 64 bits");
  for (std::size_t i = 0; i < sats.size() * sigs.size(); ++i)
    cells.push_back(r.GetUnsigned(1) != 0);
  return e;
}

}  // namespace

MsmEpoch DecodeGpsMsm(const std::string& body, MsmKind& kind) {
  const int number = MessageNumber(body);
  if (number != 1074 && number != 1077)
    throw std::invalid_argument("not a GPS MSM4/MSM7 body: message " + std::to_string(number));
  kind = number == 1074 ? MsmKind::kMsm4 : MsmKind::kMsm7;
  const bool m7 = kind == MsmKind::kMsm7;
  BitReader r(body);
  std::vector<int> sats, sigs;
  std::vector<bool> mask;
  MsmEpoch e = ReadHeader(r, sats, sigs, mask);
  const std::size_t ns = sats.size();
  std::vector<double> rough(ns), rate(ns, kNotAvailable);
  for (std::size_t i = 0; i < ns; ++i) {
    const auto v = r.GetUnsigned(8);
    rough[i] = v == 255 ? kNotAvailable : static_cast<double>(v);
  }
  if (m7) {
    for (std::size_t i = 0; i < ns; ++i) r.GetUnsigned(4);
  }
  for (std::size_t i = 0; i < ns; ++i) rough[i] += static_cast<double>(r.GetUnsigned(10)) / 1024.0;
  if (m7) {
    for (std::size_t i = 0; i < ns; ++i) {
      const std::int64_t v = r.GetSigned(14);
      rate[i] = v == -8192 ? kNotAvailable : static_cast<double>(v);
    }
  }
  for (std::size_t i = 0; i < ns; ++i) {
    e.satellites.push_back({sats[i], {}});
    for (std::size_t k = 0; k < sigs.size(); ++k) {
      if (mask[i * sigs.size() + k]) e.satellites.back().signals.push_back({sigs[k]});
    }
  }
  std::vector<MsmSignal*> cells;
  std::vector<std::size_t> owner;
  for (std::size_t i = 0; i < ns; ++i) {
    for (MsmSignal& g : e.satellites[i].signals) {
      cells.push_back(&g);
      owner.push_back(i);
    }
  }
  for (std::size_t j = 0; j < cells.size(); ++j)
    cells[j]->pseudorange_m =
        (rough[owner[j]] + Fine(r, m7 ? 20 : 15, std::ldexp(1.0, m7 ? -29 : -24))) * kLightMs_m;
  for (std::size_t j = 0; j < cells.size(); ++j)
    cells[j]->phaserange_m =
        (rough[owner[j]] + Fine(r, m7 ? 24 : 22, std::ldexp(1.0, m7 ? -31 : -29))) * kLightMs_m;
  for (MsmSignal* g : cells) {
    const auto lock = static_cast<int>(r.GetUnsigned(m7 ? 10 : 4));
    g->lock_time_s =
        m7 ? LockTimeOfMsm7Indicator(lock) : (lock == 0 ? 0.0 : std::ldexp(1.0, lock + 4) * 0.001);
  }
  for (MsmSignal* g : cells) g->half_cycle = r.GetUnsigned(1) != 0;
  for (MsmSignal* g : cells)
    g->cnr_dbhz = static_cast<double>(r.GetUnsigned(m7 ? 10 : 6)) * (m7 ? 1.0 / 16.0 : 1.0);
  for (std::size_t j = 0; j < cells.size(); ++j)
    cells[j]->phaserange_rate_mps = m7 ? rate[owner[j]] + Fine(r, 15, 0.0001) : kNotAvailable;
  if (!r.ok() || (r.position() + 7) / 8 != body.size())
    throw std::invalid_argument("MSM body length does not match its masks");
  return e;
}

}  // namespace hil::rtcm3

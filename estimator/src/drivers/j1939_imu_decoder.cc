#include "hil/estimator/drivers/j1939_imu_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "hil/estimator/drivers/arrival_stamped_imu.h"

namespace hil::estimator::drivers {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr std::uint32_t kMaxValid16 =
    0xFAFF;  // J1939: above this a field means error / not available
constexpr std::uint32_t kMaxValid24 = 0xFAFFFF;
constexpr std::uint32_t kTowUnknown = 0xFFFFF;
constexpr std::uint32_t kSecondsPerWeek = 604800;

std::uint32_t U16(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8);
}
std::uint32_t U24(const std::uint8_t* p) {
  return U16(p) | (static_cast<std::uint32_t>(p[2]) << 16);
}
std::uint32_t U32(const std::uint8_t* p) {
  return U24(p) | (static_cast<std::uint32_t>(p[3]) << 24);
}

double Latency(std::uint8_t b) { return b * 0.5e-3; }

// one 16-bit triple with resolution and offset; false when a field is error / not available
bool Triple16(const std::uint8_t* d, double res, double off, double (&out)[3]) {
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t raw = U16(d + 2 * i);
    ok = ok && raw <= kMaxValid16;
    out[i] = raw * res + off;
  }
  return ok;
}

std::array<std::uint8_t, 3> Fom(std::uint8_t b) {
  return {static_cast<std::uint8_t>(b & 3), static_cast<std::uint8_t>((b >> 2) & 3),
          static_cast<std::uint8_t>((b >> 4) & 3)};
}

}  // namespace

J1939Id ParseJ1939Id(std::uint32_t id29) {
  J1939Id out;
  out.priority = static_cast<std::uint8_t>((id29 >> 26) & 7);
  out.source = static_cast<std::uint8_t>(id29 & 0xFF);
  const std::uint32_t pf = (id29 >> 16) & 0xFF, ps = (id29 >> 8) & 0xFF, dp = (id29 >> 24) & 3;
  if (pf < 240) {
    out.pgn = (dp << 16) | (pf << 8);
    out.destination = static_cast<std::uint8_t>(ps);
  } else {
    out.pgn = (dp << 16) | (pf << 8) | ps;
  }
  return out;
}

std::optional<AriMessage> DecodeAri(const std::uint8_t* data, std::size_t len) {
  if (len < 8) return std::nullopt;
  AriMessage m;
  double v[3];
  m.available = Triple16(data, 1.0 / 128.0, -250.0, v);
  m.pitch_rate_dps = v[0];
  m.roll_rate_dps = v[1];
  m.yaw_rate_dps = v[2];
  m.figure_of_merit = Fom(data[6]);
  m.latency_s = Latency(data[7]);
  return m;
}

std::optional<AccsMessage> DecodeAccs(const std::uint8_t* data, std::size_t len) {
  if (len < 8) return std::nullopt;
  AccsMessage m;
  double v[3];
  m.available = Triple16(data, 0.01, -320.0, v);
  m.lateral_mps2 = v[0];
  m.longitudinal_mps2 = v[1];
  m.vertical_mps2 = v[2];
  m.figure_of_merit = Fom(data[6]);
  m.latency_s = Latency(data[7]);
  return m;
}

std::optional<Ssi2Message> DecodeSsi2(const std::uint8_t* data, std::size_t len) {
  if (len < 8) return std::nullopt;
  Ssi2Message m;
  const std::uint32_t pitch = U24(data), roll = U24(data + 3);
  m.available = pitch <= kMaxValid24 && roll <= kMaxValid24;
  m.pitch_deg = pitch / 32768.0 - 250.0;
  m.roll_deg = roll / 32768.0 - 250.0;
  m.pitch_compensation = data[6] & 3;
  m.pitch_figure_of_merit = (data[6] >> 2) & 3;
  m.roll_compensation = (data[6] >> 4) & 3;
  m.roll_figure_of_merit = (data[6] >> 6) & 3;
  m.latency_s = Latency(data[7]);
  return m;
}

std::optional<HilTimePulseMessage> DecodeHilTimePulse(const std::uint8_t* data, std::size_t len) {
  if (len < 8) return std::nullopt;
  HilTimePulseMessage m;
  m.tick = U32(data);
  const std::uint32_t hi = U32(data + 4);
  m.gps_tow_s = hi & 0xFFFFF;
  m.gps_week_mod4096 = static_cast<std::uint16_t>(hi >> 20);
  m.time_valid = m.gps_tow_s != kTowUnknown && m.gps_tow_s < kSecondsPerWeek;
  return m;
}

Eigen::Vector3d AngularRateFlu_radps(const AriMessage& a) {
  return Eigen::Vector3d(a.roll_rate_dps, -a.pitch_rate_dps, a.yaw_rate_dps) * kDegToRad;
}

Eigen::Vector3d SpecificForceFlu_mps2(const AccsMessage& a) {
  return {a.longitudinal_mps2, a.lateral_mps2, a.vertical_mps2};
}

std::optional<ImuSample> J1939ImuDecoder::Add(const CanRxFrame& f) {
  ++stats_.frames;
  if (!f.extended) {
    ++stats_.not_extended;
    return std::nullopt;
  }
  const J1939Id id = ParseJ1939Id(f.id & 0x1FFFFFFF);
  if (!config_.any_source && id.source != config_.source_address) {
    ++stats_.other_source;
    return std::nullopt;
  }
  if (id.pgn != kPgnAri && id.pgn != kPgnAccs && id.pgn != kPgnSsi2 && id.pgn != kPgnHilTimePulse) {
    ++stats_.unknown_pgn;
    return std::nullopt;
  }
  const std::size_t len = std::min<std::size_t>(f.len, f.data.size());
  if (len < 8) {
    ++stats_.bad_length;
    return std::nullopt;
  }
  if (have_rx_ && f.rx_ns < last_rx_ns_) ++stats_.out_of_order;
  have_rx_ = true;
  last_rx_ns_ = f.rx_ns;

  const std::int64_t window_ns = static_cast<std::int64_t>(config_.pair_window_s * 1e9);
  switch (id.pgn) {
    case kPgnAri: {
      const auto m = DecodeAri(f.data.data(), len);
      ++stats_.ari;
      if (pending_ari_) ++stats_.unpaired;
      pending_ari_.reset();
      if (!m->available) {
        ++stats_.not_available;
        return std::nullopt;
      }
      pending_ari_ = m;
      pending_ari_rx_ns_ = f.rx_ns;
      latency_s_ = m->latency_s;
      return std::nullopt;
    }
    case kPgnAccs: {
      const auto m = DecodeAccs(f.data.data(), len);
      ++stats_.accs;
      const std::optional<AriMessage> ari = pending_ari_;
      const std::int64_t ari_rx = pending_ari_rx_ns_;
      pending_ari_.reset();
      if (!m->available) {
        ++stats_.not_available;
        if (ari) ++stats_.unpaired;
        return std::nullopt;
      }
      if (!ari || std::llabs(f.rx_ns - ari_rx) > window_ns) {
        stats_.unpaired += ari ? 2 : 1;
        return std::nullopt;
      }
      return OnPair(*ari, *m, ari_rx);
    }
    case kPgnSsi2: {
      const auto m = DecodeSsi2(f.data.data(), len);
      ++stats_.ssi2;
      if (!m->available) {
        ++stats_.not_available;
        return std::nullopt;
      }
      last_slope_ = m;
      return std::nullopt;
    }
    default:
      OnPulse(*DecodeHilTimePulse(f.data.data(), len), f.rx_ns);
      return std::nullopt;
  }
}

void J1939ImuDecoder::OnPulse(const HilTimePulseMessage& p, std::int64_t rx_ns) {
  ++stats_.pulses;
  // an MCU reset: the tick restarts (going back without wrapping)
  if (have_tick_ && p.tick < last_tick_ && last_tick_ - p.tick < 0x80000000u) {
    ++stats_.mcu_resets;
    mcu_clock_.Reset();
    timer_.Reset();
    increments_.Restart();
  }
  have_tick_ = true;
  last_tick_ = p.tick;
  const std::int64_t tick = mcu_clock_.Unwrap(p.tick);
  if (!p.time_valid) {
    ++stats_.pulses_no_time;
    return;
  }
  const GpsNs gps =
      (static_cast<GpsNs>(p.gps_week_mod4096) * kSecondsPerWeek + p.gps_tow_s) * kNsPerSecond;
  mcu_clock_.AddPulse(tick, gps);
  const double latency = latency_s_ >= 0 ? latency_s_ : config_.default_latency_s;
  arrival_.AddReference(rx_ns - static_cast<std::int64_t>(std::llround(latency * 1e9)), gps);
}

std::optional<ImuSample> J1939ImuDecoder::OnPair(const AriMessage& ari, const AccsMessage& accs,
                                                 std::int64_t rx_ns) {
  const Eigen::Vector3d w = AngularRateFlu_radps(ari), f = SpecificForceFlu_mps2(accs);
  const auto measured =
      arrival_.ToGps(rx_ns - static_cast<std::int64_t>(std::llround(ari.latency_s * 1e9)));
  return AddArrivalStamped(measured, w, f, timer_, increments_, stats_);
}

}  // namespace hil::estimator::drivers
